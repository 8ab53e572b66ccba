#pragma once

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>

namespace roadscale {

// The road term of a keyframe pair whose road plane was measured on the road's pixels
// (RoadPairPlane): the earlier camera's height above that plane, the measured height per
// baseline times the distance between the two camera centres, pulled to h0 and divided by
// sigma, so that a robust loss of scale 1 counts sigmas. The plane's height comes from the
// warp of thousands of road pixels rather than from a few triangulated points, so one term
// weighs as much as many landmark terms (camera_height_residual.h).
class RoadPairResidual {
 public:
  RoadPairResidual(double height_per_baseline, double camera_height, double sigma)
      : height_per_baseline_(height_per_baseline), camera_height_(camera_height), sigma_(sigma) {}

  template <typename T>
  bool operator()(const T* anchor_cam_from_world, const T* cam_from_world, T* residual) const {
    T anchor_centre[3];
    T centre[3];
    Centre(anchor_cam_from_world, anchor_centre);
    Centre(cam_from_world, centre);
    T squared = T(0.0);
    for (int i = 0; i < 3; ++i)
      squared += (centre[i] - anchor_centre[i]) * (centre[i] - anchor_centre[i]);
    // The square root's derivative is infinite at 0; two keyframes are never in one place.
    const T baseline = squared > T(1e-24) ? sqrt(squared) : T(1e-12);
    residual[0] = (T(height_per_baseline_) * baseline - T(camera_height_)) / T(sigma_);
    return true;
  }

  static ceres::CostFunction* Create(double height_per_baseline, double camera_height,
                                     double sigma) {
    return new ceres::AutoDiffCostFunction<RoadPairResidual, 1, 6, 6>(
        new RoadPairResidual(height_per_baseline, camera_height, sigma));
  }

 private:
  // The camera centre -R^T t of a pose in PoseParameters' layout (angle-axis, translation).
  template <typename T>
  static void Centre(const T* cam_from_world, T* centre) {
    const T inverse_rotation[3] = {-cam_from_world[0], -cam_from_world[1], -cam_from_world[2]};
    const T minus_translation[3] = {-cam_from_world[3], -cam_from_world[4], -cam_from_world[5]};
    ceres::AngleAxisRotatePoint(inverse_rotation, minus_translation, centre);
  }

  double height_per_baseline_;
  double camera_height_;
  double sigma_;
};

}  // namespace roadscale
