#include "roadscale/scale/road_homography_refit.h"

#include <cmath>

#include "roadscale/util/error.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace roadscale {
namespace {

// Columns spanning the directions of w that the refit may change: all of them, or those
// perpendicular to the direction of travel.
Eigen::MatrixXd PlaneBasis(const Eigen::Vector3d& travel_direction, bool tangent_to_travel) {
  if (!tangent_to_travel) return Eigen::Matrix3d::Identity();
  Eigen::Vector3d first = travel_direction.unitOrthogonal();
  Eigen::MatrixXd basis(3, 2);
  basis.col(0) = first;
  basis.col(1) = travel_direction.cross(first).normalized();
  return basis;
}

}  // namespace

void RoadHomographyRefitOptions::Check() const {
  CheckOption(std::isfinite(loss_scale_px) && loss_scale_px > 0.0, "scale.homography_loss_scale_px",
              "must be a positive number of pixels");
  CheckOption(max_iterations >= 1, "scale.homography_max_iterations", "must be at least 1");
  CheckOption(std::isfinite(travel_prior_px_per_deg) && travel_prior_px_per_deg >= 0.0,
              "scale.homography_travel_prior_px_per_deg", "must be >= 0 pixels per degree");
}

std::optional<Eigen::Vector2d> TransferThroughRoadPlane(const Eigen::Vector2d& prev_pixel,
                                                        const Eigen::Matrix3d& rotation,
                                                        const Eigen::Vector3d& translation,
                                                        const Eigen::Vector3d& w,
                                                        const PinholeCamera& camera) {
  const Eigen::Vector3d ray = camera.Unproject(prev_pixel);
  const Eigen::Vector3d p = rotation * ray + translation * w.dot(ray);
  if (!(p.z() > 0.0)) return std::nullopt;
  return camera.Project(p);
}

std::optional<RoadHomographyRefit> RefitRoadHomography(
    const std::vector<Eigen::Vector2d>& prev_pixels, const std::vector<Eigen::Vector2d>& cur_pixels,
    const std::vector<int>& indices, const Rigid3d& cur_from_prev, const PinholeCamera& camera,
    const Plane& initial, const RoadHomographyRefitOptions& options) {
  options.Check();
  if (indices.size() < 6 || !(initial.height > 0.0)) return std::nullopt;
  if (!TravelDirection(cur_from_prev)) return std::nullopt;
  const Eigen::Vector3d t = cur_from_prev.translation().normalized();
  const int plane_unknowns = options.tangent_to_travel ? 2 : 3;
  const int unknowns = plane_unknowns + (options.refine_rotation ? 3 : 0);

  Eigen::Matrix3d rotation = cur_from_prev.linear();
  Eigen::Vector3d w = initial.normal / initial.height;

  RoadHomographyRefit result;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    // The direction of travel follows the refined rotation; tangent to travel, w is kept
    // perpendicular to it (its length, 1 / h, unchanged).
    const Eigen::Vector3d travel_direction = -rotation.transpose() * t;
    const Eigen::MatrixXd basis = PlaneBasis(travel_direction, options.tangent_to_travel);
    if (options.tangent_to_travel) {
      const double length = w.norm();
      w = (w - w.dot(travel_direction) * travel_direction).normalized() * length;
    }
    Eigen::MatrixXd normal_matrix = Eigen::MatrixXd::Zero(unknowns, unknowns);
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(unknowns);
    double squared_sum = 0.0;
    for (int index : indices) {
      const Eigen::Vector3d ray = camera.Unproject(prev_pixels[index]);
      const Eigen::Vector3d rotated = rotation * ray;
      const Eigen::Vector3d p = rotated + t * w.dot(ray);
      if (!(p.z() > 0.0)) return std::nullopt;
      const Eigen::Vector2d residual = camera.Project(p) - cur_pixels[index];
      Eigen::Matrix<double, 2, 3> projection;
      projection << camera.fx / p.z(), 0.0, -camera.fx * p.x() / (p.z() * p.z()), 0.0,
          camera.fy / p.z(), -camera.fy * p.y() / (p.z() * p.z());
      Eigen::MatrixXd jacobian(2, unknowns);
      jacobian.leftCols(plane_unknowns) = projection * t * ray.transpose() * basis;
      // exp(dw) R r = R r + dw x (R r): the derivative is -[R r]x.
      if (options.refine_rotation) jacobian.rightCols(3) = -projection * SkewMatrix(rotated);
      const double norm = residual.norm();
      const double weight = norm <= options.loss_scale_px ? 1.0 : options.loss_scale_px / norm;
      normal_matrix += weight * jacobian.transpose() * jacobian;
      gradient += weight * jacobian.transpose() * residual;
      squared_sum += residual.squaredNorm();
    }
    if (!options.tangent_to_travel && options.travel_prior_px_per_deg > 0.0) {
      // One more residual: the angle between the plane and the travel, in pixels.
      const double px_per_rad = options.travel_prior_px_per_deg * 180.0 / M_PI;
      Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(1, unknowns);
      jacobian.leftCols(3) = px_per_rad * travel_direction.transpose() / w.norm();
      const double residual = px_per_rad * w.dot(travel_direction) / w.norm();
      normal_matrix += jacobian.transpose() * jacobian;
      gradient += jacobian.transpose() * residual;
    }
    result.rms_px = std::sqrt(squared_sum / static_cast<double>(indices.size()));
    const Eigen::LDLT<Eigen::MatrixXd> solver(normal_matrix);
    if (solver.info() != Eigen::Success || !solver.isPositive()) return std::nullopt;
    const Eigen::VectorXd step = solver.solve(-gradient);
    if (!step.allFinite()) return std::nullopt;
    w += basis * step.head(plane_unknowns);
    if (options.refine_rotation) rotation = ExpSo3(step.tail(3)) * rotation;
    result.iterations = iteration + 1;
    // Converged when the plane's height changes by less than 1e-7 of itself.
    if ((basis * step.head(plane_unknowns)).norm() < 1e-7 * w.norm() &&
        (!options.refine_rotation || step.tail(3).norm() < 1e-9)) {
      break;
    }
  }
  const double w_norm = w.norm();
  if (!(w_norm > 0.0) || !std::isfinite(w_norm)) return std::nullopt;
  result.plane.normal = w / w_norm;
  result.plane.height = 1.0 / w_norm;
  if (result.plane.normal.dot(initial.normal) < 0.0) return std::nullopt;
  result.rotation = rotation;
  result.rotation_change_rad = RotationAngle(rotation * cur_from_prev.linear().transpose());
  return result;
}

}  // namespace roadscale
