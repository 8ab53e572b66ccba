#include "roadscale/scale/road_corridor.h"

#include <cmath>

#include "roadscale/scale/road_plane.h"
#include "roadscale/util/error.h"

namespace roadscale {

void RoadCorridorOptions::Check() const {
  CheckOption(std::isfinite(half_width_m) && half_width_m > 0.0, "corridor.half_width_m",
              "must be a positive number of metres");
  CheckOption(std::isfinite(max_distance_m) && max_distance_m > 0.0, "corridor.max_distance_m",
              "must be a positive number of metres");
}

RoadFootprint FootprintOnRoad(const Eigen::Vector2d& pixel, const PinholeCamera& camera,
                              const Eigen::Vector3d& road_normal,
                              const Eigen::Vector3d& travel_direction, double camera_height_m) {
  RoadFootprint footprint;
  const Eigen::Vector3d ray = camera.Unproject(pixel);
  const double down = road_normal.dot(ray);
  if (!ray.allFinite() || !(down > 0.0)) return footprint;
  const Eigen::Vector3d point = ray * (camera_height_m / down);
  // The travel direction is perpendicular to n_r (RoadNormalFromMotion); the lateral axis
  // n_r x d points right for n_r down and d forward.
  const Eigen::Vector3d lateral_axis = road_normal.cross(travel_direction).normalized();
  footprint.ahead = travel_direction.dot(point);
  footprint.lateral = lateral_axis.dot(point);
  footprint.valid = footprint.ahead > 0.0;
  return footprint;
}

double YawAboutRoadNormal(const Rigid3d& cur_from_prev, const Eigen::Vector3d& road_normal) {
  const Eigen::Vector3d prev_heading = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d cur_heading = cur_from_prev.linear().transpose() * prev_heading;
  const auto in_plane = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(v - road_normal.dot(v) * road_normal);
  };
  const Eigen::Vector3d a = in_plane(prev_heading);
  const Eigen::Vector3d b = in_plane(cur_heading);
  return std::atan2(road_normal.dot(a.cross(b)), a.dot(b));
}

std::vector<int> SelectRoadCorridor(const std::vector<Eigen::Vector2d>& pixels,
                                    const PinholeCamera& camera, const Rigid3d& cur_from_prev,
                                    const Eigen::Vector3d& road_normal, double camera_height_m,
                                    double step_m, const RoadCorridorOptions& options) {
  std::vector<int> selected;
  const std::optional<Eigen::Vector3d> travel = TravelDirection(cur_from_prev);
  if (!travel) return selected;
  // d is perpendicular to n_r for the motion's road normal; for another reference normal
  // (fixed pitch) the travel line is taken in the road plane.
  const Eigen::Vector3d along = (*travel - road_normal.dot(*travel) * road_normal).normalized();
  double yaw = 0.0;
  double curvature = 0.0;
  if (options.follow_turn && std::isfinite(step_m) && step_m > 0.0) {
    yaw = YawAboutRoadNormal(cur_from_prev, road_normal);
    curvature = yaw / step_m;
  }
  for (size_t i = 0; i < pixels.size(); ++i) {
    const RoadFootprint footprint =
        FootprintOnRoad(pixels[i], camera, road_normal, along, camera_height_m);
    if (!footprint.valid || footprint.ahead > options.max_distance_m) continue;
    const double s = footprint.ahead;
    const double path = 0.5 * curvature * s * s - 0.5 * yaw * s;
    if (std::abs(footprint.lateral - path) > options.half_width_m) continue;
    selected.push_back(static_cast<int>(i));
  }
  return selected;
}

}  // namespace roadscale
