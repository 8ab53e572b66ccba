#include "roadscale/scale/road_plane.h"

#include <cmath>

namespace roadscale {

double Plane::PitchRad() const { return std::atan2(normal.z(), normal.y()); }

double Plane::RollRad() const { return std::atan2(-normal.x(), normal.y()); }

std::optional<Plane> PlaneThroughPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c,
                                        const Eigen::Vector3d& reference_normal) {
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const Eigen::Vector3d cross = ab.cross(ac);
  const double norm = cross.norm();
  // Relative to the edge lengths: the sine of the angle at `a` must not vanish.
  if (!(norm > 1e-9 * ab.norm() * ac.norm()) || !std::isfinite(norm)) return std::nullopt;
  Plane plane;
  plane.normal = cross / norm;
  if (plane.normal.dot(reference_normal) < 0.0) plane.normal = -plane.normal;
  plane.height = plane.normal.dot(a);
  return plane;
}

double AngleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

std::optional<Eigen::Vector3d> TravelDirection(const Rigid3d& cur_from_prev) {
  const Eigen::Vector3d centre_of_cur =
      -cur_from_prev.linear().transpose() * cur_from_prev.translation();
  const double length = centre_of_cur.norm();
  if (!std::isfinite(length) || length < 1e-12) return std::nullopt;
  return Eigen::Vector3d(centre_of_cur / length);
}

std::optional<Eigen::Vector3d> RoadNormalFromMotion(const Rigid3d& cur_from_prev) {
  const std::optional<Eigen::Vector3d> travel = TravelDirection(cur_from_prev);
  if (!travel) return std::nullopt;
  const Eigen::Vector3d down = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d normal = down - down.dot(*travel) * *travel;
  // |normal| is the cosine of the travel direction's elevation.
  if (normal.norm() < std::sin(M_PI / 180.0)) return std::nullopt;
  return Eigen::Vector3d(normal.normalized());
}

Eigen::Vector3d RoadNormalFromCameraPitch(double pitch_rad) {
  return {0.0, std::cos(pitch_rad), std::sin(pitch_rad)};
}

}  // namespace roadscale
