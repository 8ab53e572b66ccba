#pragma once

#include <vector>

#include <Eigen/Core>

namespace roadscale {

struct SampsonRefinementOptions {
  // Levenberg-Marquardt iterations; the minimal-sample RANSAC model is close, so a few do.
  int max_iterations = 10;
  // Robust loss on the Sampson error (normalised image coordinates times the focal length,
  // i.e. roughly pixels) and its scale. Huber is convex: for correspondences already known
  // to be inliers. Cauchy's influence falls off beyond the scale: for a set that still
  // holds outliers.
  enum class Loss { kHuber, kCauchy };
  Loss loss = Loss::kHuber;
  double loss_scale_px = 1.0;
  // Stop when the relative decrease of the cost falls below this.
  double relative_tolerance = 1e-10;

  // Throws Error naming the first invalid option.
  void Check() const;
};

struct SampsonRefinementResult {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // cur_from_prev
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();    // unit translation, cur_from_prev
  double initial_rms_px = 0.0;  // root mean square Sampson error before and after
  double final_rms_px = 0.0;
  int iterations = 0;
};

// Refines a relative pose (5 degrees of freedom: rotation and translation direction) so that
// the Sampson errors of the correspondences are least squares (Huber-weighted). `prev` and
// `cur` are normalised image coordinates (K^-1 x, z = 1) of the same points in the previous
// and current frame; `focal_px` only scales the errors to pixels. The translation stays a
// unit vector (updated in its tangent plane), so scale is never introduced.
SampsonRefinementResult RefineRelativePoseSampson(const Eigen::Matrix3d& rotation,
                                                  const Eigen::Vector3d& direction,
                                                  const std::vector<Eigen::Vector2d>& prev,
                                                  const std::vector<Eigen::Vector2d>& cur,
                                                  double focal_px,
                                                  const SampsonRefinementOptions& options);

// Sampson error (normalised coordinates times focal_px) of one correspondence under
// E = [t]x R, signed: compare its absolute value with a threshold.
double SampsonErrorPx(const Eigen::Matrix3d& essential, const Eigen::Vector2d& prev,
                      const Eigen::Vector2d& cur, double focal_px);

}  // namespace roadscale
