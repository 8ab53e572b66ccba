#include "roadscale/scale/inverse_depth_plane.h"

#include <cmath>

#include <Eigen/Cholesky>

namespace roadscale {

double InverseDepthSensitivity(const Eigen::Vector3d& ray, double rho,
                               const Rigid3d& cur_from_prev) {
  const double length = cur_from_prev.translation().norm();
  if (!(length > 0.0) || !std::isfinite(length)) return 0.0;
  // rho * X_cur = R r + rho t: the same image point, without the division by depth.
  const Eigen::Vector3d a = cur_from_prev.linear() * ray;
  const Eigen::Vector3d b = cur_from_prev.translation() / length;
  const double z = a.z() + rho * b.z();
  if (!(std::abs(z) > 0.0)) return 0.0;
  const Eigen::Vector2d shift((b.x() * a.z() - a.x() * b.z()) / (z * z),
                              (b.y() * a.z() - a.y() * b.z()) / (z * z));
  return shift.norm();
}

std::optional<Plane> FitPlaneInverseDepth(const std::vector<Eigen::Vector3d>& points,
                                          const std::vector<int>& indices,
                                          const Rigid3d& cur_from_prev,
                                          const Eigen::Vector3d& reference_normal,
                                          bool weight_by_precision) {
  if (indices.size() < 3) return std::nullopt;
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right_side = Eigen::Vector3d::Zero();
  for (int index : indices) {
    const Eigen::Vector3d& point = points[index];
    if (!(point.z() > 0.0) || !point.allFinite()) return std::nullopt;
    const double rho = 1.0 / point.z();
    const Eigen::Vector3d ray = point * rho;
    double weight = 1.0;
    if (weight_by_precision) {
      const double sensitivity = InverseDepthSensitivity(ray, rho, cur_from_prev);
      weight = sensitivity * sensitivity;
    }
    normal_matrix += weight * ray * ray.transpose();
    right_side += weight * rho * ray;
  }
  // Rays of collinear points span a plane only: the fit is then undetermined.
  const Eigen::LDLT<Eigen::Matrix3d> solver(normal_matrix);
  const Eigen::Vector3d diagonal = solver.vectorD().cwiseAbs();
  if (solver.info() != Eigen::Success || !(diagonal.minCoeff() > 1e-12 * diagonal.maxCoeff())) {
    return std::nullopt;
  }
  const Eigen::Vector3d w = solver.solve(right_side);
  const double norm = w.norm();
  if (!std::isfinite(norm) || !(norm > 0.0)) return std::nullopt;
  Plane plane;
  plane.normal = w / norm;
  plane.height = 1.0 / norm;
  // A plane whose normal points away from the road has the camera below it.
  if (plane.normal.dot(reference_normal) < 0.0) return std::nullopt;
  return plane;
}

}  // namespace roadscale
