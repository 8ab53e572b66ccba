#include "roadscale/scale/triangulation.h"

#include <cmath>
#include <string>

#include "roadscale/scale/road_plane.h"
#include "roadscale/util/error.h"

#include <Eigen/SVD>

namespace roadscale {

void TriangulationOptions::Check() const {
  CheckOption(std::isfinite(min_parallax_deg) && min_parallax_deg >= 0.0 && min_parallax_deg < 90.0,
              "triangulation.min_parallax_deg", "must be in [0, 90)");
  CheckOption(std::isfinite(max_reprojection_error_px) && max_reprojection_error_px > 0.0,
              "triangulation.max_reprojection_error_px", "must be a positive number");
}

TriangulatedPoints TriangulateUnitBaseline(const std::vector<Eigen::Vector2d>& prev_pixels,
                                           const std::vector<Eigen::Vector2d>& cur_pixels,
                                           const Rigid3d& cur_from_prev,
                                           const PinholeCamera& camera,
                                           const TriangulationOptions& options) {
  if (prev_pixels.size() != cur_pixels.size()) {
    throw Error("triangulation: " + std::to_string(prev_pixels.size()) + " previous pixels but " +
                std::to_string(cur_pixels.size()) +
                " current pixels; expected one current pixel per previous pixel");
  }
  TriangulatedPoints result;
  const double baseline = cur_from_prev.translation().norm();
  if (!std::isfinite(baseline) || baseline <= 0.0) return result;
  const Eigen::Matrix3d rotation = cur_from_prev.linear();
  const Eigen::Vector3d translation = cur_from_prev.translation() / baseline;
  const Eigen::Vector3d centre_of_cur = -rotation.transpose() * translation;
  Eigen::Matrix<double, 3, 4> cur_projection;
  cur_projection << rotation, translation;
  const double min_parallax_rad = options.min_parallax_deg * M_PI / 180.0;
  const double max_error_sq = options.max_reprojection_error_px * options.max_reprojection_error_px;

  result.points.reserve(prev_pixels.size());
  result.track_indices.reserve(prev_pixels.size());
  for (size_t i = 0; i < prev_pixels.size(); ++i) {
    const Eigen::Vector3d prev_ray = camera.Unproject(prev_pixels[i]);
    const Eigen::Vector3d cur_ray = camera.Unproject(cur_pixels[i]);
    if (!prev_ray.allFinite() || !cur_ray.allFinite()) continue;
    // Rows x * P.row(2) - P.row(0) and y * P.row(2) - P.row(1) of both cameras.
    Eigen::Matrix4d design;
    design.row(0) << -1.0, 0.0, prev_ray.x(), 0.0;
    design.row(1) << 0.0, -1.0, prev_ray.y(), 0.0;
    design.row(2) = cur_ray.x() * cur_projection.row(2) - cur_projection.row(0);
    design.row(3) = cur_ray.y() * cur_projection.row(2) - cur_projection.row(1);
    const Eigen::JacobiSVD<Eigen::Matrix4d> svd(design, Eigen::ComputeFullV);
    const Eigen::Vector4d homogeneous = svd.matrixV().col(3);
    // A point at (or beyond) infinity has no parallax at all.
    if (std::abs(homogeneous.w()) < 1e-12 * homogeneous.head<3>().norm()) {
      ++result.num_small_parallax;
      continue;
    }
    const Eigen::Vector3d point = homogeneous.head<3>() / homogeneous.w();
    const Eigen::Vector3d point_in_cur = rotation * point + translation;
    if (point.z() <= 0.0 || point_in_cur.z() <= 0.0) {
      ++result.num_behind_camera;
      continue;
    }
    if (AngleBetween(point, point - centre_of_cur) < min_parallax_rad) {
      ++result.num_small_parallax;
      continue;
    }
    if ((camera.Project(point) - prev_pixels[i]).squaredNorm() > max_error_sq ||
        (camera.Project(point_in_cur) - cur_pixels[i]).squaredNorm() > max_error_sq) {
      ++result.num_large_reprojection_error;
      continue;
    }
    result.points.push_back(point);
    result.track_indices.push_back(static_cast<int>(i));
  }
  return result;
}

}  // namespace roadscale
