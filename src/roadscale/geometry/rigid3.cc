#include "roadscale/geometry/rigid3.h"

#include <cmath>

#include <Eigen/SVD>

namespace roadscale {

Rigid3d MakeRigid3d(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  Rigid3d transform = Rigid3d::Identity();
  transform.linear() = rotation;
  transform.translation() = translation;
  return transform;
}

double RotationAngle(const Eigen::Matrix3d& rotation) {
  // atan2 of sine and cosine keeps precision near 0 and pi, where acos alone loses it.
  const Eigen::Vector3d axis_times_sine(rotation(2, 1) - rotation(1, 2),
                                        rotation(0, 2) - rotation(2, 0),
                                        rotation(1, 0) - rotation(0, 1));
  const double cosine = 0.5 * (rotation.trace() - 1.0);
  return std::atan2(0.5 * axis_times_sine.norm(), cosine);
}

Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& matrix) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(matrix, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
  correction(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * correction * svd.matrixV().transpose();
}

Eigen::Matrix3d SkewMatrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d skew;
  skew << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return skew;
}

Eigen::Matrix3d ExpSo3(const Eigen::Vector3d& omega) {
  const double angle = omega.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

}  // namespace roadscale
