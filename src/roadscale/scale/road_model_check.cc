#include "roadscale/scale/road_model_check.h"

#include <cmath>
#include <string>

#include "roadscale/scale/delaunay.h"
#include "roadscale/scale/road_plane.h"
#include "roadscale/util/error.h"

namespace roadscale {

void RoadModelCheckOptions::Check() const {
  CheckOption(reference == Reference::kMotion || reference == Reference::kFixedPitch,
              "road_model.reference", "must be motion or fixed-pitch");
  CheckOption(std::isfinite(camera_pitch_deg) && std::abs(camera_pitch_deg) < 45.0,
              "road_model.camera_pitch_deg", "must be within (-45, 45) degrees");
  CheckOption(std::isfinite(max_angle_deg) && max_angle_deg > 0.0 && max_angle_deg <= 90.0,
              "road_model.max_angle_deg", "must be in (0, 90] degrees");
}

std::optional<Eigen::Vector3d> ExpectedRoadNormal(const Rigid3d& cur_from_prev,
                                                  const RoadModelCheckOptions& options) {
  if (options.reference == RoadModelCheckOptions::Reference::kFixedPitch) {
    return RoadNormalFromCameraPitch(options.camera_pitch_deg * M_PI / 180.0);
  }
  return RoadNormalFromMotion(cur_from_prev);
}

RoadModelCheck CheckRoadModel(const std::vector<Eigen::Vector2d>& pixels,
                              const std::vector<Eigen::Vector3d>& points,
                              const Eigen::Vector3d& road_normal,
                              const RoadModelCheckOptions& options) {
  if (pixels.size() != points.size()) {
    throw Error("road-model check: " + std::to_string(pixels.size()) + " pixels but " +
                std::to_string(points.size()) + " points; expected one point per pixel");
  }
  RoadModelCheck result;
  const std::vector<std::array<int, 3>> triangles = DelaunayTriangles(pixels);
  result.num_triangles = static_cast<int>(triangles.size());
  const double max_angle_rad = options.max_angle_deg * M_PI / 180.0;
  std::vector<bool> in_road_triangle(points.size(), false);
  for (const std::array<int, 3>& triangle : triangles) {
    const std::optional<Plane> plane = PlaneThroughPoints(points[triangle[0]], points[triangle[1]],
                                                          points[triangle[2]], road_normal);
    if (!plane || !(plane->height > 0.0)) continue;
    if (!(AngleBetween(plane->normal, road_normal) < max_angle_rad)) continue;
    ++result.num_accepted_triangles;
    for (int index : triangle) in_road_triangle[index] = true;
  }
  for (size_t i = 0; i < points.size(); ++i) {
    if (in_road_triangle[i]) result.kept.push_back(static_cast<int>(i));
  }
  return result;
}

}  // namespace roadscale
