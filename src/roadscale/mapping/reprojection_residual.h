#pragma once

#include <ceres/sized_cost_function.h>

#include "roadscale/geometry/pinhole_camera.h"

#include <Eigen/Core>

namespace roadscale {

// Pixel error of a world point seen by a camera (parameters: the cam_from_world pose as in
// pose_parameters.h, the point), with analytic Jacobians: Ceres' automatic derivatives of the
// same error cost about half of a keyframe's bundle adjustment (docs/benchmark-history.md,
// "Keyframe back end"). A point less than kMinDepthInFront in front of the camera fails the
// evaluation (Ceres then rejects the step) rather than projecting through the centre, which would
// flip it to the image.
constexpr double kMinDepthInFront = 1e-6;

class ReprojectionResidual : public ceres::SizedCostFunction<2, 6, 3> {
 public:
  ReprojectionResidual(const PinholeCamera& camera, const Eigen::Vector2d& observed);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  static ceres::CostFunction* Create(const PinholeCamera& camera, const Eigen::Vector2d& observed) {
    return new ReprojectionResidual(camera, observed);
  }

 private:
  double fx_, fy_, cx_, cy_;
  Eigen::Vector2d observed_;
};

// The same error of a known point for a pose alone (motion-only refinement).
class PoseOnlyReprojectionResidual : public ceres::SizedCostFunction<2, 6> {
 public:
  PoseOnlyReprojectionResidual(const PinholeCamera& camera, const Eigen::Vector2d& observed,
                               const Eigen::Vector3d& point_world)
      : residual_(camera, observed), point_(point_world) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  static ceres::CostFunction* Create(const PinholeCamera& camera, const Eigen::Vector2d& observed,
                                     const Eigen::Vector3d& point_world) {
    return new PoseOnlyReprojectionResidual(camera, observed, point_world);
  }

 private:
  ReprojectionResidual residual_;
  Eigen::Vector3d point_;
};

}  // namespace roadscale
