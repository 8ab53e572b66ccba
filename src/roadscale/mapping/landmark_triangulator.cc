#include "roadscale/mapping/landmark_triangulator.h"

#include <cmath>

#include "roadscale/util/error.h"

#include <Eigen/SVD>

namespace roadscale {
namespace {

Eigen::Vector3d RayInWorld(const PointView& view, const PinholeCamera& camera) {
  return (view.cam_from_world.linear().transpose() * camera.Unproject(view.pixel)).normalized();
}

// The linear (DLT) triangulation of two views in normalised image coordinates.
std::optional<Eigen::Vector3d> TriangulateTwoViews(const PointView& a, const PointView& b,
                                                   const PinholeCamera& camera) {
  Eigen::Matrix4d design;
  const PointView* views[2] = {&a, &b};
  for (int v = 0; v < 2; ++v) {
    const Eigen::Vector3d ray = camera.Unproject(views[v]->pixel);
    const Eigen::Matrix<double, 3, 4> projection = views[v]->cam_from_world.matrix().topRows<3>();
    design.row(2 * v) = ray.x() * projection.row(2) - projection.row(0);
    design.row(2 * v + 1) = ray.y() * projection.row(2) - projection.row(1);
  }
  const Eigen::JacobiSVD<Eigen::Matrix4d> svd(design, Eigen::ComputeFullV);
  const Eigen::Vector4d homogeneous = svd.matrixV().col(3);
  if (std::abs(homogeneous.w()) < 1e-12) return std::nullopt;
  return Eigen::Vector3d(homogeneous.head<3>() / homogeneous.w());
}

}  // namespace

void LandmarkTriangulatorOptions::Check() const {
  CheckOption(min_parallax_deg >= 0.0 && min_parallax_deg < 90.0,
              "mapping.landmark_min_parallax_deg", "must be in [0, 90) degrees");
  CheckOption(max_reprojection_error_px > 0.0, "mapping.landmark_max_reprojection_error_px",
              "must be > 0");
  CheckOption(max_depth_below_ground >= 0.0 && std::isfinite(max_depth_below_ground),
              "mapping.landmark_max_depth_below_ground",
              "must be >= 0 camera heights (0: no check)");
}

std::optional<Eigen::Vector3d> TriangulateMultiView(const std::vector<PointView>& views,
                                                    const PinholeCamera& camera,
                                                    const LandmarkTriangulatorOptions& options) {
  if (views.size() < 2) return std::nullopt;
  // The widest pair: the earliest view with each later one (the window's views are in
  // order of time, and while driving the baseline grows with time).
  size_t best = 1;
  double best_cos = 2.0;
  const Eigen::Vector3d first_ray = RayInWorld(views.front(), camera);
  for (size_t v = 1; v < views.size(); ++v) {
    const double cos_angle = first_ray.dot(RayInWorld(views[v], camera));
    if (cos_angle < best_cos) {
      best_cos = cos_angle;
      best = v;
    }
  }
  if (best_cos > std::cos(options.min_parallax_deg * M_PI / 180.0)) return std::nullopt;
  const std::optional<Eigen::Vector3d> point =
      TriangulateTwoViews(views.front(), views[best], camera);
  if (!point || !point->allFinite()) return std::nullopt;
  for (const PointView& view : views) {
    const Eigen::Vector3d point_cam = view.cam_from_world * *point;
    if (point_cam.z() <= 0.0) return std::nullopt;
    if ((camera.Project(point_cam) - view.pixel).norm() > options.max_reprojection_error_px) {
      return std::nullopt;
    }
  }
  return point;
}

int TriangulateNewLandmarks(const PinholeCamera& camera, const LandmarkTriangulatorOptions& options,
                            LocalWindow* window) {
  if (window->keyframes().size() < 2) return 0;
  const Keyframe& newest = window->keyframes().back();
  int created = 0;
  std::vector<PointView> views;
  for (const auto& [id, pixel] : newest.observations) {
    if (window->landmarks().count(id) > 0) continue;
    views.clear();
    for (const Keyframe& keyframe : window->keyframes()) {
      const auto observation = keyframe.observations.find(id);
      if (observation != keyframe.observations.end()) {
        views.push_back({keyframe.cam_from_world, observation->second});
      }
    }
    const std::optional<Eigen::Vector3d> point = TriangulateMultiView(views, camera, options);
    if (!point) continue;
    Landmark landmark;
    landmark.position = *point;
    window->landmarks().emplace(id, landmark);
    ++created;
  }
  return created;
}

int RemoveLandmarksBelowGround(const Plane& ground, const LandmarkTriangulatorOptions& options,
                               LocalWindow* window) {
  if (options.max_depth_below_ground <= 0.0 || window->keyframes().empty()) return 0;
  // Near the horizon the flat ground says nothing: with the road normal a degree off, a tree
  // 200 m away on the horizon lies 3.5 m "below" the road. Only rays that meet the ground
  // within this many camera heights (2.9 degrees or more below the horizon) are checked; a
  // post caught 15 m ahead lies on a ray 6 degrees down.
  constexpr double kMaxGroundDistanceHeights = 20.0;
  const Rigid3d& newest = window->keyframes().back().cam_from_world;
  const double deepest = (1.0 + options.max_depth_below_ground) * ground.height;
  std::vector<int64_t> below;
  for (const auto& [id, landmark] : window->landmarks()) {
    const Eigen::Vector3d point = newest * landmark.position;
    const double down = ground.normal.dot(point.normalized());
    if (down >= 1.0 / kMaxGroundDistanceHeights && ground.normal.dot(point) > deepest) {
      below.push_back(id);
    }
  }
  for (int64_t id : below) window->RemoveTrack(id);
  return static_cast<int>(below.size());
}

}  // namespace roadscale
