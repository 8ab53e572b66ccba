#include "roadscale/scale/road_plane_ransac.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "roadscale/geometry/angles.h"
#include "roadscale/util/error.h"
#include "roadscale/util/random.h"

#include <Eigen/Eigenvalues>

namespace roadscale {
namespace {

constexpr int kMaxRefitRounds = 5;

struct Consensus {
  int count = 0;
  double sum_squared = 0.0;

  bool BetterThan(const Consensus& other) const {
    return count > other.count || (count == other.count && sum_squared < other.sum_squared);
  }
};

Consensus Score(const std::vector<Eigen::Vector3d>& points, const Plane& plane,
                double relative_threshold) {
  Consensus consensus;
  const double threshold = relative_threshold * plane.height;
  for (const Eigen::Vector3d& point : points) {
    const double distance = std::abs(plane.SignedDistance(point));
    if (distance < threshold) {
      ++consensus.count;
      consensus.sum_squared += distance * distance;
    }
  }
  return consensus;
}

std::vector<int> Inliers(const std::vector<Eigen::Vector3d>& points, const Plane& plane,
                         double relative_threshold) {
  std::vector<int> inliers;
  const double threshold = relative_threshold * plane.height;
  for (size_t i = 0; i < points.size(); ++i) {
    if (std::abs(plane.SignedDistance(points[i])) < threshold) {
      inliers.push_back(static_cast<int>(i));
    }
  }
  return inliers;
}

// RoadPlaneRansacOptions::max_tilt_deg.
bool WithinTilt(const Plane& plane, const Eigen::Vector3d& reference_normal,
                const RoadPlaneRansacOptions& options) {
  if (options.max_tilt_deg <= 0.0) return true;
  const double cosine = plane.normal.dot(reference_normal.normalized());
  return cosine >= std::cos(options.max_tilt_deg * kRadiansPerDegree);
}

}  // namespace

void RoadPlaneRansacOptions::Check() const {
  CheckOption(min_points >= 3, "ransac.min_points", "must be at least 3");
  CheckOption(std::isfinite(inlier_threshold) && inlier_threshold > 0.0 && inlier_threshold < 1.0,
              "ransac.inlier_threshold", "must be in (0, 1) (a fraction of the plane's height)");
  CheckOption(max_iterations >= 1, "ransac.max_iterations", "must be at least 1");
  CheckOption(std::isfinite(confidence) && confidence > 0.0 && confidence < 1.0,
              "ransac.confidence", "must be in (0, 1)");
  CheckOption(std::isfinite(max_tilt_deg) && max_tilt_deg >= 0.0 && max_tilt_deg < 90.0,
              "ransac.max_tilt_deg", "must be in [0, 90) degrees (0: any tilt)");
}

std::optional<Plane> FitPlaneLeastSquares(const std::vector<Eigen::Vector3d>& points,
                                          const std::vector<int>& indices,
                                          const Eigen::Vector3d& reference_normal) {
  if (indices.size() < 3) return std::nullopt;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int index : indices) centroid += points[index];
  centroid /= static_cast<double>(indices.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (int index : indices) {
    const Eigen::Vector3d offset = points[index] - centroid;
    scatter += offset * offset.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  if (solver.info() != Eigen::Success) return std::nullopt;
  const Eigen::Vector3d spread = solver.eigenvalues();  // ascending
  // Collinear points spread along one direction only.
  if (!(spread(1) > 1e-12 * spread(2))) return std::nullopt;
  Plane plane;
  plane.normal = solver.eigenvectors().col(0);
  if (plane.normal.dot(reference_normal) < 0.0) plane.normal = -plane.normal;
  plane.height = plane.normal.dot(centroid);
  return plane;
}

RoadPlaneFit FitRoadPlaneRansac(const std::vector<Eigen::Vector3d>& points,
                                const Eigen::Vector3d& reference_normal,
                                const RoadPlaneRansacOptions& options) {
  RoadPlaneFit fit;
  const int num_points = static_cast<int>(points.size());
  if (num_points < std::max(3, options.min_points)) {
    fit.status = RoadPlaneFit::Status::kTooFewPoints;
    return fit;
  }
  fit.status = RoadPlaneFit::Status::kDegenerate;

  Rng rng(options.seed);
  std::optional<Plane> best_plane;
  Consensus best;
  int needed_iterations = options.max_iterations;
  int iteration = 0;
  for (; iteration < needed_iterations; ++iteration) {
    const int a = rng.UniformInt(0, num_points - 1);
    const int b = rng.UniformInt(0, num_points - 1);
    const int c = rng.UniformInt(0, num_points - 1);
    if (a == b || a == c || b == c) continue;
    const std::optional<Plane> plane =
        PlaneThroughPoints(points[a], points[b], points[c], reference_normal);
    if (!plane || !(plane->height > 0.0) || !WithinTilt(*plane, reference_normal, options))
      continue;
    const Consensus consensus = Score(points, *plane, options.inlier_threshold);
    if (!best_plane || consensus.BetterThan(best)) {
      best_plane = plane;
      best = consensus;
      const double inlier_fraction = static_cast<double>(best.count) / num_points;
      const double all_inlier_sample = std::pow(inlier_fraction, 3);
      if (all_inlier_sample >= 1.0) {
        needed_iterations = 0;
      } else if (all_inlier_sample > 0.0) {
        const double estimate =
            std::log(1.0 - options.confidence) / std::log(1.0 - all_inlier_sample);
        needed_iterations = static_cast<int>(
            std::min<double>(options.max_iterations, std::ceil(std::max(estimate, 1.0))));
      }
    }
  }
  fit.iterations = iteration;
  if (!best_plane || best.count < 3) return fit;

  Plane plane = *best_plane;
  std::vector<int> inliers = Inliers(points, plane, options.inlier_threshold);
  for (int round = 0; round < kMaxRefitRounds; ++round) {
    const std::optional<Plane> refit = FitPlaneLeastSquares(points, inliers, reference_normal);
    if (!refit || !(refit->height > 0.0)) return fit;
    if (!WithinTilt(*refit, reference_normal, options)) break;
    plane = *refit;
    std::vector<int> refit_inliers = Inliers(points, plane, options.inlier_threshold);
    if (refit_inliers == inliers) break;
    if (refit_inliers.size() < 3) return fit;
    inliers = std::move(refit_inliers);
  }
  fit.status = RoadPlaneFit::Status::kOk;
  fit.plane = plane;
  fit.inliers = std::move(inliers);
  fit.inlier_ratio = static_cast<double>(fit.inliers.size()) / num_points;
  return fit;
}

}  // namespace roadscale
