#include "roadscale/mapping/reprojection_residual.h"

#include <cmath>
#include <limits>

#include "roadscale/geometry/rigid3.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace roadscale {
namespace {

// R(w) p for the angle-axis w, with its derivatives by w and by p. The value repeats
// ceres::AngleAxisRotatePoint operation for operation (so the residuals are those Ceres'
// automatic derivatives evaluated), including its first-order form for angles whose square
// is below machine epsilon, whose derivatives are then those of that form.
void RotatePoint(const double* w, const double* p, Eigen::Vector3d* rotated,
                 Eigen::Matrix3d* by_rotation, Eigen::Matrix3d* by_point) {
  const double theta2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  if (theta2 > std::numeric_limits<double>::epsilon()) {
    const double theta = std::sqrt(theta2);
    const double costheta = std::cos(theta);
    const double sintheta = std::sin(theta);
    const double theta_inverse = 1.0 / theta;
    const double axis[3] = {w[0] * theta_inverse, w[1] * theta_inverse, w[2] * theta_inverse};
    const double axis_cross_point[3] = {axis[1] * p[2] - axis[2] * p[1],
                                        axis[2] * p[0] - axis[0] * p[2],
                                        axis[0] * p[1] - axis[1] * p[0]};
    const double tmp = (axis[0] * p[0] + axis[1] * p[1] + axis[2] * p[2]) * (1.0 - costheta);
    for (int i = 0; i < 3; ++i) {
      (*rotated)[i] = p[i] * costheta + axis_cross_point[i] * sintheta + axis[i] * tmp;
    }
    const Eigen::Vector3d unit(axis[0], axis[1], axis[2]);
    const Eigen::Matrix3d unit_skew = SkewMatrix(unit);
    if (by_point != nullptr) {
      *by_point = costheta * Eigen::Matrix3d::Identity() + sintheta * unit_skew +
                  (1.0 - costheta) * unit * unit.transpose();
    }
    if (by_rotation != nullptr) {
      // d(R p)/dw = -[q]x J(w) with q = R p and J the left Jacobian of SO(3),
      // I + a [u]x + b [u]x^2 (u the unit axis, a = (1 - cos) / theta, b = 1 - sin / theta);
      // expanded with [q]x [u]x = u q^T - (q.u) I so that no 3x3 product is needed.
      const Eigen::Vector3d& q = *rotated;
      const double a = (1.0 - costheta) * theta_inverse;
      const double b = 1.0 - sintheta * theta_inverse;
      const double q_dot_u = q.dot(unit);
      *by_rotation = -SkewMatrix(q) - a * (unit * q.transpose()) -
                     b * (unit * q.cross(unit).transpose()) +
                     (a * q_dot_u) * Eigen::Matrix3d::Identity() + (b * q_dot_u) * unit_skew;
    }
  } else {
    // R p ~ p + w x p.
    const double w_cross_point[3] = {w[1] * p[2] - w[2] * p[1], w[2] * p[0] - w[0] * p[2],
                                     w[0] * p[1] - w[1] * p[0]};
    for (int i = 0; i < 3; ++i) (*rotated)[i] = p[i] + w_cross_point[i];
    if (by_point != nullptr) {
      *by_point = Eigen::Matrix3d::Identity() + SkewMatrix(Eigen::Vector3d(w[0], w[1], w[2]));
    }
    if (by_rotation != nullptr) *by_rotation = -SkewMatrix(Eigen::Vector3d(p[0], p[1], p[2]));
  }
}

}  // namespace

ReprojectionResidual::ReprojectionResidual(const PinholeCamera& camera,
                                           const Eigen::Vector2d& observed)
    : fx_(camera.fx), fy_(camera.fy), cx_(camera.cx), cy_(camera.cy), observed_(observed) {}

bool ReprojectionResidual::Evaluate(double const* const* parameters, double* residuals,
                                    double** jacobians) const {
  const double* cam_from_world = parameters[0];
  const bool pose_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
  const bool point_jacobian = jacobians != nullptr && jacobians[1] != nullptr;
  Eigen::Vector3d point_cam;
  Eigen::Matrix3d by_rotation;
  Eigen::Matrix3d by_point;
  RotatePoint(cam_from_world, parameters[1], &point_cam, pose_jacobian ? &by_rotation : nullptr,
              point_jacobian ? &by_point : nullptr);
  for (int i = 0; i < 3; ++i) point_cam[i] += cam_from_world[3 + i];
  if (point_cam[2] < kMinDepthInFront) return false;
  // Multiplied by the inverse depth, as Ceres' Jet divides.
  const double inverse_z = 1.0 / point_cam[2];
  residuals[0] = fx_ * point_cam[0] * inverse_z + cx_ - observed_.x();
  residuals[1] = fy_ * point_cam[1] * inverse_z + cy_ - observed_.y();
  if (!pose_jacobian && !point_jacobian) return true;

  // The projection's derivative by the point in the camera.
  Eigen::Matrix<double, 2, 3> projection;
  projection << fx_ * inverse_z, 0.0, -fx_ * point_cam[0] * inverse_z * inverse_z, 0.0,
      fy_ * inverse_z, -fy_ * point_cam[1] * inverse_z * inverse_z;
  if (pose_jacobian) {
    Eigen::Map<Eigen::Matrix<double, 2, 6, Eigen::RowMajor>> jacobian(jacobians[0]);
    jacobian.leftCols<3>() = projection * by_rotation;
    jacobian.rightCols<3>() = projection;
  }
  if (point_jacobian) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> jacobian(jacobians[1]);
    jacobian = projection * by_point;
  }
  return true;
}

bool PoseOnlyReprojectionResidual::Evaluate(double const* const* parameters, double* residuals,
                                            double** jacobians) const {
  const double* both[2] = {parameters[0], point_.data()};
  double* pose_jacobian[2] = {jacobians != nullptr ? jacobians[0] : nullptr, nullptr};
  return residual_.Evaluate(both, residuals, pose_jacobian);
}

}  // namespace roadscale
