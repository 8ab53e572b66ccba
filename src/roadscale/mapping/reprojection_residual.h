#pragma once

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>

#include "roadscale/geometry/pinhole_camera.h"

#include <Eigen/Core>

namespace roadscale {

// Pixel error of a world point seen by a camera (parameters: the cam_from_world pose as in
// pose_parameters.h, the point). A point behind the camera gives a large constant error
// rather than a projection through the centre, which would flip to the image.
class ReprojectionResidual {
 public:
  ReprojectionResidual(const PinholeCamera& camera, const Eigen::Vector2d& observed)
      : fx_(camera.fx), fy_(camera.fy), cx_(camera.cx), cy_(camera.cy), observed_(observed) {}

  template <typename T>
  bool operator()(const T* cam_from_world, const T* point_world, T* residual) const {
    T point_cam[3];
    ceres::AngleAxisRotatePoint(cam_from_world, point_world, point_cam);
    for (int i = 0; i < 3; ++i) point_cam[i] += cam_from_world[3 + i];
    if (point_cam[2] < T(1e-6)) return false;
    residual[0] = T(fx_) * point_cam[0] / point_cam[2] + T(cx_) - T(observed_.x());
    residual[1] = T(fy_) * point_cam[1] / point_cam[2] + T(cy_) - T(observed_.y());
    return true;
  }

  static ceres::CostFunction* Create(const PinholeCamera& camera, const Eigen::Vector2d& observed) {
    return new ceres::AutoDiffCostFunction<ReprojectionResidual, 2, 6, 3>(
        new ReprojectionResidual(camera, observed));
  }

 private:
  double fx_, fy_, cx_, cy_;
  Eigen::Vector2d observed_;
};

// The same error of a known point for a pose alone (motion-only refinement).
class PoseOnlyReprojectionResidual {
 public:
  PoseOnlyReprojectionResidual(const PinholeCamera& camera, const Eigen::Vector2d& observed,
                               const Eigen::Vector3d& point_world)
      : residual_(camera, observed), point_(point_world) {}

  template <typename T>
  bool operator()(const T* cam_from_world, T* residual) const {
    const T point[3] = {T(point_.x()), T(point_.y()), T(point_.z())};
    return residual_(cam_from_world, point, residual);
  }

  static ceres::CostFunction* Create(const PinholeCamera& camera, const Eigen::Vector2d& observed,
                                     const Eigen::Vector3d& point_world) {
    return new ceres::AutoDiffCostFunction<PoseOnlyReprojectionResidual, 2, 6>(
        new PoseOnlyReprojectionResidual(camera, observed, point_world));
  }

 private:
  ReprojectionResidual residual_;
  Eigen::Vector3d point_;
};

}  // namespace roadscale
