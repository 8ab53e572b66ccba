#include "roadscale/mapping/steady_road_normal.h"

#include <cmath>
#include <string>

#include "roadscale/scale/road_plane.h"
#include "roadscale/util/error.h"

namespace roadscale {

SteadyRoadNormal::SteadyRoadNormal(double max_turn_deg)
    : max_turn_rad_(max_turn_deg * M_PI / 180.0) {
  if (!(max_turn_deg > 0.0 && max_turn_deg <= 90.0)) {
    throw Error(
        "steady road normal: the largest turn between keyframes must be in (0, 90] "
        "degrees, got " +
        std::to_string(max_turn_deg));
  }
}

Eigen::Vector3d SteadyRoadNormal::Next(const Eigen::Vector3d& pair_normal) {
  const auto agrees = [&](const std::optional<Eigen::Vector3d>& other) {
    return other && AngleBetween(pair_normal, *other) <= max_turn_rad_;
  };
  const bool pair_is_noise = taken_ && !agrees(taken_) && !agrees(last_pair_);
  last_pair_ = pair_normal;
  if (!pair_is_noise) taken_ = pair_normal;
  return *taken_;
}

}  // namespace roadscale
