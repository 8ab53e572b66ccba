#pragma once

#include <optional>

#include <Eigen/Core>

namespace roadscale {

// The road's normal under the newest keyframe, from one keyframe pair after another: each
// pair's own normal (perpendicular to its travel, RoadNormalFromMotion) where it agrees with
// the last one taken, the last one taken where it does not.
//
// Why: the travel of a pair the car barely moved between has no direction worth the name. On
// the real traffic drive, stopping, keyframes 44 -> 50 travelled 17 degrees "down", and the
// plane perpendicular to that took 52 of the map's 84 landmarks for points below the road;
// the frames before them could no longer be localised and the trajectory jumped 0.27 m in
// one frame (docs/benchmark-history.md, "A stopping car's ground"). The car's travel turns against
// its camera only by the grade's change and the body's pitch, a few degrees between
// keyframes, so a pair's normal further than `max_turn_deg` from the last one taken is that
// pair's noise. Unless the pair before it says the same: then the last one taken was the
// wrong one, and holding it would lock the map to it.
class SteadyRoadNormal {
 public:
  // Throws Error unless 0 < max_turn_deg <= 90 (the road model's own range for its angle).
  explicit SteadyRoadNormal(double max_turn_deg);

  // The normal to use for the newest pair, whose own normal is `pair_normal` (unit length).
  Eigen::Vector3d Next(const Eigen::Vector3d& pair_normal);

 private:
  double max_turn_rad_;
  std::optional<Eigen::Vector3d> taken_;      // the last normal returned
  std::optional<Eigen::Vector3d> last_pair_;  // the last pair's own normal
};

}  // namespace roadscale
