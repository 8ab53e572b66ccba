#pragma once

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>

#include <Eigen/Core>

namespace roadscale {

// The road term of the bundle adjustment: a road landmark lies h0 below its anchor keyframe,
// measured along the road normal found there (the sign convention of road_plane.h: the
// normal points from the camera to the road, so the height n·X_cam is positive). Divided by
// sigma, the spread of true road points about a plane (camber, wear: a few centimetres),
// so that a robust loss of scale 1 treats the residual as a number of sigmas.
//
// Why each landmark under its own keyframe rather than one plane per window: a window spans
// tens of metres, over which the grade and the camber change (hills, crossings), while
// every keyframe's camera stays h0 above the road under it. The normal is fixed at the
// pair's fit: it does not depend on the scale, and with it fixed the term pulls on the
// scale (and on each landmark along the normal) only. A landmark whose depth the images
// determine poorly moves along its ray at little reprojection cost instead of pulling the
// scale, so near, well-observed road points decide the scale, as they should.
class CameraHeightResidual {
 public:
  CameraHeightResidual(const Eigen::Vector3d& normal_in_cam, double camera_height, double sigma)
      : normal_(normal_in_cam), camera_height_(camera_height), sigma_(sigma) {}

  template <typename T>
  bool operator()(const T* anchor_cam_from_world, const T* point_world, T* residual) const {
    T point_cam[3];
    ceres::AngleAxisRotatePoint(anchor_cam_from_world, point_world, point_cam);
    T height = T(0.0);
    for (int i = 0; i < 3; ++i) {
      height += T(normal_[i]) * (point_cam[i] + anchor_cam_from_world[3 + i]);
    }
    residual[0] = (height - T(camera_height_)) / T(sigma_);
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Vector3d& normal_in_cam, double camera_height,
                                     double sigma) {
    return new ceres::AutoDiffCostFunction<CameraHeightResidual, 1, 6, 3>(
        new CameraHeightResidual(normal_in_cam, camera_height, sigma));
  }

 private:
  Eigen::Vector3d normal_;
  double camera_height_;
  double sigma_;
};

}  // namespace roadscale
