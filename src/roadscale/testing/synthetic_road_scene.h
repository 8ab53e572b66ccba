#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/scale/road_plane.h"

#include <Eigen/Core>

namespace roadscale::testing {

// What a synthetic point lies on.
enum class SceneLabel { kRoad, kWall, kCar, kAboveHorizon };

// A synthetic street in the previous camera's frame, in metres: a road plane, walls along
// both sides, a parked car (a box standing on the road) and points above the horizon.
struct SceneOptions {
  Plane road{Eigen::Vector3d::UnitY(), 1.65};
  int num_road = 400;
  int num_wall = 150;
  int num_car = 80;
  int num_above_horizon = 60;
  uint32_t seed = 1;
};

struct ScenePoint {
  Eigen::Vector3d point;
  SceneLabel label = SceneLabel::kRoad;
};

std::vector<ScenePoint> MakeStreetScene(const SceneOptions& options);

// Points on `plane` at lateral offsets in [x_min, x_max] and depths in [z_min, z_max].
std::vector<Eigen::Vector3d> PointsOnPlane(const Plane& plane, int count, double x_min,
                                           double x_max, double z_min, double z_max, uint32_t seed);

// The scene seen from the previous camera and from cur_from_prev (metric), with Gaussian
// pixel noise of `noise_px` on both images; only points in front of both cameras and inside
// both images are kept.
struct TwoViewObservations {
  std::vector<Eigen::Vector2d> prev_pixels;
  std::vector<Eigen::Vector2d> cur_pixels;
  std::vector<SceneLabel> labels;
  std::vector<Eigen::Vector3d> points;  // noise-free, previous camera frame, metres
};

TwoViewObservations ObserveTwoViews(const std::vector<ScenePoint>& scene,
                                    const Rigid3d& cur_from_prev, const PinholeCamera& camera,
                                    double noise_px, uint32_t seed);

// A road mask of the camera's size: discs of `radius_px` around the previous pixels of the
// observations whose label is in `road_labels`.
cv::Mat MaskFromLabels(const TwoViewObservations& observations, const PinholeCamera& camera,
                       const std::vector<SceneLabel>& road_labels, int radius_px);

// The motion of a camera that drives `step_m` along the road plane `road` (grade follows the
// plane) while turning by `yaw_rad` about the road normal.
Rigid3d DriveAlongRoad(const Plane& road, double step_m, double yaw_rad);

}  // namespace roadscale::testing
