#include "roadscale/testing/synthetic_road_scene.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "roadscale/util/random.h"

namespace roadscale::testing {
namespace {

// Two unit vectors spanning the plane: one across the road (x-like), one along it (z-like).
void PlaneAxes(const Plane& plane, Eigen::Vector3d* across, Eigen::Vector3d* along) {
  *along = (Eigen::Vector3d::UnitZ() - plane.normal.z() * plane.normal).normalized();
  *across = along->cross(plane.normal).normalized();
  if (across->x() < 0.0) *across = -*across;
}

}  // namespace

std::vector<Eigen::Vector3d> PointsOnPlane(const Plane& plane, int count, double x_min,
                                           double x_max, double z_min, double z_max,
                                           uint32_t seed) {
  Rng rng(seed);
  Eigen::Vector3d across;
  Eigen::Vector3d along;
  PlaneAxes(plane, &across, &along);
  const Eigen::Vector3d foot = plane.height * plane.normal;
  std::vector<Eigen::Vector3d> points;
  points.reserve(count);
  for (int i = 0; i < count; ++i) {
    // One draw a statement here and below: the order of an expression's operands is the
    // compiler's, and a seed must give the same scene with every compiler.
    const double ahead = rng.Uniform(z_min, z_max);
    const double aside = rng.Uniform(x_min, x_max);
    points.push_back(foot + aside * across + ahead * along);
  }
  return points;
}

std::vector<ScenePoint> MakeStreetScene(const SceneOptions& options) {
  Rng rng(options.seed);
  std::vector<ScenePoint> scene;
  for (const Eigen::Vector3d& point :
       PointsOnPlane(options.road, options.num_road, -7.0, 7.0, 4.0, 30.0, options.seed + 1)) {
    scene.push_back({point, SceneLabel::kRoad});
  }
  Eigen::Vector3d across;
  Eigen::Vector3d along;
  PlaneAxes(options.road, &across, &along);
  const Eigen::Vector3d foot = options.road.height * options.road.normal;
  const Eigen::Vector3d up = -options.road.normal;
  // Walls 8 m to either side, from the road up to 6 m.
  for (int i = 0; i < options.num_wall; ++i) {
    const double side = i % 2 == 0 ? -8.0 : 8.0;
    const double height = rng.Uniform(0.0, 6.0);
    const double ahead = rng.Uniform(6.0, 50.0);
    scene.push_back({foot + side * across + ahead * along + height * up, SceneLabel::kWall});
  }
  // A parked car: a 1.8 m x 1.5 m x 4.5 m box on the road, 2.5 m to the right, 9 m ahead;
  // points on its rear face, its left side and its roof.
  for (int i = 0; i < options.num_car; ++i) {
    const double a = rng.Uniform();
    const double b = rng.Uniform();
    Eigen::Vector3d offset;
    switch (i % 3) {
      case 0:
        offset = (1.6 + 1.8 * a) * across + 9.0 * along + 1.5 * b * up;
        break;
      case 1:
        offset = 1.6 * across + (9.0 + 4.5 * a) * along + 1.5 * b * up;
        break;
      default:
        offset = (1.6 + 1.8 * a) * across + (9.0 + 4.5 * b) * along + 1.5 * up;
        break;
    }
    scene.push_back({foot + offset, SceneLabel::kCar});
  }
  // Trees and buildings above the camera, far ahead.
  for (int i = 0; i < options.num_above_horizon; ++i) {
    const double height = options.road.height + rng.Uniform(1.0, 9.0);
    const double ahead = rng.Uniform(20.0, 80.0);
    const double aside = rng.Uniform(-15.0, 15.0);
    scene.push_back(
        {foot + aside * across + ahead * along + height * up, SceneLabel::kAboveHorizon});
  }
  return scene;
}

TwoViewObservations ObserveTwoViews(const std::vector<ScenePoint>& scene,
                                    const Rigid3d& cur_from_prev, const PinholeCamera& camera,
                                    double noise_px, uint32_t seed) {
  Rng rng(seed);
  TwoViewObservations observations;
  for (const ScenePoint& scene_point : scene) {
    const Eigen::Vector3d in_cur = cur_from_prev * scene_point.point;
    if (scene_point.point.z() <= 0.1 || in_cur.z() <= 0.1) continue;
    Eigen::Vector2d prev = camera.Project(scene_point.point);
    Eigen::Vector2d cur = camera.Project(in_cur);
    if (noise_px > 0.0) {
      const double prev_dy = rng.Normal();
      const double prev_dx = rng.Normal();
      const double cur_dy = rng.Normal();
      const double cur_dx = rng.Normal();
      prev += noise_px * Eigen::Vector2d(prev_dx, prev_dy);
      cur += noise_px * Eigen::Vector2d(cur_dx, cur_dy);
    }
    if (!camera.IsInside(prev) || !camera.IsInside(cur)) continue;
    observations.prev_pixels.push_back(prev);
    observations.cur_pixels.push_back(cur);
    observations.labels.push_back(scene_point.label);
    observations.points.push_back(scene_point.point);
  }
  return observations;
}

cv::Mat MaskFromLabels(const TwoViewObservations& observations, const PinholeCamera& camera,
                       const std::vector<SceneLabel>& road_labels, int radius_px) {
  cv::Mat mask(camera.height, camera.width, CV_8UC1, cv::Scalar(0));
  for (size_t i = 0; i < observations.labels.size(); ++i) {
    if (std::find(road_labels.begin(), road_labels.end(), observations.labels[i]) ==
        road_labels.end()) {
      continue;
    }
    const Eigen::Vector2d& pixel = observations.prev_pixels[i];
    cv::circle(mask, cv::Point(cvRound(pixel.x()), cvRound(pixel.y())), radius_px, cv::Scalar(255),
               cv::FILLED);
  }
  return mask;
}

Rigid3d DriveAlongRoad(const Plane& road, double step_m, double yaw_rad) {
  Eigen::Vector3d across;
  Eigen::Vector3d along;
  PlaneAxes(road, &across, &along);
  // prev_from_cur: the current camera is `step_m` ahead along the road, turned about the
  // road's normal.
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw_rad, road.normal).toRotationMatrix();
  const Rigid3d prev_from_cur = MakeRigid3d(turn, step_m * along);
  return prev_from_cur.inverse();
}

}  // namespace roadscale::testing
