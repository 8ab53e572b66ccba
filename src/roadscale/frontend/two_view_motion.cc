#include "roadscale/frontend/two_view_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "roadscale/util/error.h"
#include "roadscale/util/median.h"
#include "roadscale/util/random.h"

#include <Eigen/SVD>

namespace roadscale {
namespace {

// Refine / re-select rounds; the inlier set usually stops changing after two or three.
constexpr int kMaxRefinementRounds = 5;

// The rotation that best maps the bearings `from` onto `to` (least squares, Kabsch).
Eigen::Matrix3d FitRotation(const std::vector<Eigen::Vector3d>& from,
                            const std::vector<Eigen::Vector3d>& to,
                            const std::vector<size_t>& subset) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (size_t i : subset) m += to[i] * from[i].transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

// Pixel distance between the current position and the previous one moved by rotation R
// alone: the parallax of the correspondence, or infinity when R turns it behind the camera.
// `prev_ray` is camera.Unproject(c.prev), passed in so that the rotation RANSAC computes it
// once per correspondence rather than once per hypothesis.
double RotationResidualPx(const PinholeCamera& camera, const Eigen::Matrix3d& R,
                          const Eigen::Vector3d& prev_ray, const Eigen::Vector2d& cur) {
  const Eigen::Vector3d ray = R * prev_ray;
  if (ray.z() <= 0.0) return std::numeric_limits<double>::infinity();
  return (camera.Project(ray) - cur).norm();
}

struct RotationFit {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  std::vector<size_t> inliers;
};

// Rotation-only model by RANSAC on two-point samples, refitted on its inliers: what the
// image motion would be without any translation.
RotationFit FitRotationRansac(const std::vector<Correspondence>& correspondences,
                              const PinholeCamera& camera, const TwoViewMotionOptions& options) {
  const size_t n = correspondences.size();
  std::vector<Eigen::Vector3d> prev_rays(n);
  std::vector<Eigen::Vector3d> from(n);
  std::vector<Eigen::Vector3d> to(n);
  for (size_t i = 0; i < n; ++i) {
    prev_rays[i] = camera.Unproject(correspondences[i].prev);
    from[i] = prev_rays[i].normalized();
    to[i] = camera.Unproject(correspondences[i].cur).normalized();
  }
  // The inliers of R (RotationResidualPx below the threshold, with the same arithmetic), or
  // fewer than `to_beat` of them: counting stops once the rest cannot reach `to_beat`. Under
  // translation most hypotheses lose and most correspondences miss by far more than the
  // threshold, so those are rejected on one coordinate before the square root.
  const double threshold = options.ransac_threshold_px;
  const auto inliers_of = [&](const Eigen::Matrix3d& R, size_t to_beat) {
    std::vector<size_t> inliers;
    for (size_t i = 0; i < n; ++i) {
      if (inliers.size() + (n - i) < to_beat) break;
      const Eigen::Vector3d ray = R * prev_rays[i];
      if (ray.z() <= 0.0) continue;
      const Eigen::Vector2d& cur = correspondences[i].cur;
      const Eigen::Vector2d error(camera.fx * ray.x() / ray.z() + camera.cx - cur.x(),
                                  camera.fy * ray.y() / ray.z() + camera.cy - cur.y());
      if (std::abs(error.x()) >= 2.0 * threshold || std::abs(error.y()) >= 2.0 * threshold) {
        continue;
      }
      if (error.norm() < threshold) inliers.push_back(i);
    }
    return inliers;
  };

  Rng rng(options.seed);
  const auto pick = [&rng, n] {
    return static_cast<size_t>(rng.UniformInt(0, static_cast<int>(n) - 1));
  };
  RotationFit best;
  int needed = options.ransac_max_iterations;
  for (int iteration = 0; iteration < needed && iteration < options.ransac_max_iterations;
       ++iteration) {
    const size_t a = pick();
    size_t b = pick();
    if (a == b) b = (b + 1) % n;
    const Eigen::Matrix3d R = FitRotation(from, to, {a, b});
    std::vector<size_t> inliers = inliers_of(R, best.inliers.size() + 1);
    if (inliers.size() <= best.inliers.size()) continue;
    best.rotation = R;
    best.inliers = std::move(inliers);
    const double w = static_cast<double>(best.inliers.size()) / static_cast<double>(n);
    const double p_fail = 1.0 - w * w;
    if (p_fail <= 0.0) break;
    needed =
        static_cast<int>(std::ceil(std::log(1.0 - options.ransac_confidence) / std::log(p_fail)));
  }
  if (best.inliers.size() >= 2) {
    best.rotation = FitRotation(from, to, best.inliers);
    best.inliers = inliers_of(best.rotation, 0);
  }
  return best;
}

Eigen::Matrix3d EssentialFromMotion(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Eigen::Matrix3d skew;
  skew << 0.0, -t.z(), t.y(), t.z(), 0.0, -t.x(), -t.y(), t.x(), 0.0;
  return skew * R;
}

struct Decomposition {
  Eigen::Matrix3d rotation;
  Eigen::Vector3d direction;
};

// The motion (R, t) with E = [t]x R that the camera made. E gives two rotations, 180 degrees
// apart about the baseline, and t up to sign. The rotation is the one nearer the
// rotation-only estimate (never wrong by 180 degrees); the sign of t is the one that puts the
// correspondences in front of both cameras, each voting with the sine of its parallax angle.
// (OpenCV's recoverPose counts only points nearer than 50 baselines: after a stop, with a
// baseline of a few centimetres, that leaves a handful of points, and it returned the twisted
// rotation or the reversed direction on synthetic stop-and-go scenes.)
Decomposition DecomposeEssential(const Eigen::Matrix3d& E, const Eigen::Matrix3d& rotation_hint,
                                 const std::vector<Correspondence>& correspondences,
                                 const std::vector<size_t>& subset, const PinholeCamera& camera) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(E, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  Eigen::Matrix3d V = svd.matrixV();
  if (U.determinant() < 0.0) U = -U;
  if (V.determinant() < 0.0) V = -V;
  Eigen::Matrix3d W;
  W << 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d R1 = U * W * V.transpose();
  const Eigen::Matrix3d R2 = U * W.transpose() * V.transpose();
  Decomposition result;
  result.rotation =
      RotationAngle(R1.transpose() * rotation_hint) <= RotationAngle(R2.transpose() * rotation_hint)
          ? R1
          : R2;
  result.direction = U.col(2).normalized();

  double votes = 0.0;  // > 0: +t puts the points in front of both cameras
  for (size_t i : subset) {
    const Eigen::Vector3d b1 = result.rotation * camera.Unproject(correspondences[i].prev);
    const Eigen::Vector3d b2 = camera.Unproject(correspondences[i].cur);
    // d2 b2 = d1 b1 + t, solved for the depths d1 (along b1) and d2 (along b2).
    const Eigen::Vector3d c = b1.cross(b2);
    const double c2 = c.squaredNorm();
    if (c2 <= 0.0) continue;
    const double d1 = -result.direction.cross(b2).dot(c) / c2;
    const double d2 = -result.direction.cross(b1).dot(c) / c2;
    const double weight = std::sqrt(c2) / (b1.norm() * b2.norm());
    if (d1 > 0.0 && d2 > 0.0) votes += weight;
    if (d1 < 0.0 && d2 < 0.0) votes -= weight;
  }
  if (votes < 0.0) result.direction = -result.direction;
  return result;
}

double MedianParallaxPx(const std::vector<Correspondence>& correspondences,
                        const PinholeCamera& camera, const Eigen::Matrix3d& R,
                        const std::vector<size_t>& subset) {
  std::vector<double> residuals;
  residuals.reserve(subset.size());
  for (size_t i : subset) {
    const Correspondence& c = correspondences[i];
    residuals.push_back(RotationResidualPx(camera, R, camera.Unproject(c.prev), c.cur));
  }
  return Median(std::move(residuals));
}

}  // namespace

std::string MotionStatusName(MotionStatus status) {
  switch (status) {
    case MotionStatus::kOk:
      return "ok";
    case MotionStatus::kFirstFrame:
      return "first_frame";
    case MotionStatus::kStationary:
      return "stationary";
    case MotionStatus::kPureRotation:
      return "pure_rotation";
    case MotionStatus::kTooFewTracks:
      return "too_few_tracks";
    case MotionStatus::kTooFewInliers:
      return "too_few_inliers";
  }
  return "unknown";
}

void TwoViewMotionOptions::Check() const {
  CheckOption(std::isfinite(ransac_threshold_px) && ransac_threshold_px > 0.0,
              "motion.ransac_threshold_px", "must be positive");
  CheckOption(ransac_confidence > 0.0 && ransac_confidence < 1.0, "motion.ransac_confidence",
              "must be in (0, 1)");
  CheckOption(ransac_max_iterations >= 1, "motion.ransac_max_iterations", "must be at least 1");
  CheckOption(min_correspondences >= 5, "motion.min_correspondences",
              "must be at least 5 (the five-point solver's sample)");
  CheckOption(min_inliers >= 5, "motion.min_inliers", "must be at least 5");
  CheckOption(min_inlier_ratio >= 0.0 && min_inlier_ratio <= 1.0, "motion.min_inlier_ratio",
              "must be in [0, 1]");
  CheckOption(std::isfinite(stationary_flow_px) && stationary_flow_px >= 0.0,
              "motion.stationary_flow_px", "must be non-negative");
  CheckOption(std::isfinite(min_parallax_px) && min_parallax_px >= 0.0, "motion.min_parallax_px",
              "must be non-negative");
  CheckOption(std::isfinite(refinement_inlier_sigmas) && refinement_inlier_sigmas >= 0.0,
              "motion.refinement_inlier_sigmas", "must be non-negative");
  CheckOption(refinement_epipole_exclusion_deg >= 0.0 && refinement_epipole_exclusion_deg < 90.0,
              "motion.refinement_epipole_exclusion_deg", "must be in [0, 90)");
  refinement.Check();
}

Rigid3d TwoViewMotion::CurFromPrev(double length) const {
  return MakeRigid3d(rotation, direction * length);
}

TwoViewMotion EstimateTwoViewMotion(const std::vector<Correspondence>& correspondences,
                                    const PinholeCamera& camera,
                                    const TwoViewMotionOptions& options) {
  options.Check();
  camera.Check();
  TwoViewMotion motion;
  const size_t n = correspondences.size();
  motion.num_correspondences = static_cast<int>(n);
  std::vector<size_t> all(n);
  for (size_t i = 0; i < n; ++i) all[i] = i;
  {
    std::vector<double> flow;
    flow.reserve(n);
    for (const Correspondence& c : correspondences) flow.push_back((c.cur - c.prev).norm());
    motion.flow_px = Median(std::move(flow));
  }
  if (static_cast<int>(n) < options.min_correspondences) {
    motion.status = MotionStatus::kTooFewTracks;
    return motion;
  }
  const auto set_inliers = [&](const std::vector<size_t>& inliers) {
    motion.inlier_track_ids.clear();
    for (size_t i : inliers) motion.inlier_track_ids.push_back(correspondences[i].track_id);
    motion.num_inliers = static_cast<int>(inliers.size());
    motion.inlier_ratio = static_cast<double>(inliers.size()) / static_cast<double>(n);
  };

  if (motion.flow_px < options.stationary_flow_px) {
    motion.status = MotionStatus::kStationary;
    motion.parallax_px = motion.flow_px;
    set_inliers(all);
    return motion;
  }

  const RotationFit rotation_only = FitRotationRansac(correspondences, camera, options);
  const double rotation_parallax =
      MedianParallaxPx(correspondences, camera, rotation_only.rotation, all);
  if (rotation_parallax < options.min_parallax_px) {
    motion.status = MotionStatus::kPureRotation;
    motion.rotation = rotation_only.rotation;
    motion.parallax_px = rotation_parallax;
    set_inliers(rotation_only.inliers);
    return motion;
  }

  std::vector<cv::Point2d> prev_px(n);
  std::vector<cv::Point2d> cur_px(n);
  for (size_t i = 0; i < n; ++i) {
    prev_px[i] = {correspondences[i].prev.x(), correspondences[i].prev.y()};
    cur_px[i] = {correspondences[i].cur.x(), correspondences[i].cur.y()};
  }
  cv::Mat K;
  cv::eigen2cv(camera.K(), K);
  // OpenCV 4.6's findEssentialMat RANSAC seeds its own generator (its result does not change
  // with cv::theRNG()'s state); theRNG (per thread) is seeded anyway so that a version that
  // draws from it stays deterministic.
  cv::theRNG().state = options.seed;
  cv::Mat ransac_mask;
  const cv::Mat E_all =
      cv::findEssentialMat(prev_px, cur_px, K, cv::RANSAC, options.ransac_confidence,
                           options.ransac_threshold_px, options.ransac_max_iterations, ransac_mask);
  if (E_all.rows < 3 || E_all.cols != 3) {
    motion.status = MotionStatus::kTooFewInliers;
    return motion;
  }
  Eigen::Matrix3d E;
  cv::cv2eigen(cv::Mat(E_all.rowRange(0, 3)), E);
  std::vector<size_t> ransac_inliers;
  for (size_t i = 0; i < n; ++i) {
    if (ransac_mask.at<unsigned char>(static_cast<int>(i)) != 0) ransac_inliers.push_back(i);
  }
  const Decomposition pose =
      DecomposeEssential(E, rotation_only.rotation, correspondences, ransac_inliers, camera);
  Eigen::Matrix3d R = pose.rotation;
  Eigen::Vector3d t = pose.direction;

  std::vector<size_t> inliers = ransac_inliers;

  const double focal = 0.5 * (camera.fx + camera.fy);
  std::vector<Eigen::Vector2d> prev_norm(n);
  std::vector<Eigen::Vector2d> cur_norm(n);
  for (size_t i = 0; i < n; ++i) {
    prev_norm[i] = camera.Unproject(correspondences[i].prev).head<2>();
    cur_norm[i] = camera.Unproject(correspondences[i].cur).head<2>();
  }
  const auto rms_of = [&](const Eigen::Matrix3d& essential, const std::vector<size_t>& subset) {
    double sum = 0.0;
    for (size_t i : subset) {
      const double e = SampsonErrorPx(essential, prev_norm[i], cur_norm[i], focal);
      sum += e * e;
    }
    return subset.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(subset.size()));
  };
  motion.sampson_rms_px = rms_of(EssentialFromMotion(R, t), inliers);
  motion.refined_sampson_rms_px = motion.sampson_rms_px;

  if (options.refine && inliers.size() >= 5) {
    const auto refine_on = [&](const std::vector<size_t>& subset,
                               const SampsonRefinementOptions& refinement) {
      // Near the epipole a small move of the epipole puts any wrong track on its epipolar
      // line, so such tracks hold the solution in a false minimum; their short flow says
      // little about the direction anyway. They are left out of the fit (not of the inliers).
      const double min_cos = std::cos(options.refinement_epipole_exclusion_deg * M_PI / 180.0);
      std::vector<Eigen::Vector2d> prev_subset;
      std::vector<Eigen::Vector2d> cur_subset;
      for (size_t i : subset) {
        if (std::abs(cur_norm[i].homogeneous().normalized().dot(t)) > min_cos) continue;
        prev_subset.push_back(prev_norm[i]);
        cur_subset.push_back(cur_norm[i]);
      }
      const SampsonRefinementResult refined =
          RefineRelativePoseSampson(R, t, prev_subset, cur_subset, focal, refinement);
      R = refined.rotation;
      t = refined.direction;
    };
    // The five-point model can be degrees off, and its inlier set is then chosen by the wrong
    // model: refining on it alone settles on a consistent but wrong (set, model) pair. So the
    // first round uses every correspondence with a Cauchy loss at the RANSAC threshold (far
    // outliers have almost no weight, near-misses still pull).
    SampsonRefinementOptions robust = options.refinement;
    robust.loss = SampsonRefinementOptions::Loss::kCauchy;
    robust.loss_scale_px = options.ransac_threshold_px;
    refine_on(all, robust);
    // Then rounds on the correspondences within refinement_inlier_sigmas robust standard
    // deviations (1.4826 x median absolute Sampson error) of the model, until the set is
    // stable: the RANSAC threshold is loose compared with the tracks' noise, and wrong
    // tracks within it bias the direction.
    std::vector<size_t> subset;
    for (int round = 0; round < kMaxRefinementRounds; ++round) {
      const Eigen::Matrix3d E_round = EssentialFromMotion(R, t);
      std::vector<double> residuals(n);
      std::vector<double> inlier_residuals;
      for (size_t i = 0; i < n; ++i) {
        residuals[i] = std::abs(SampsonErrorPx(E_round, prev_norm[i], cur_norm[i], focal));
        if (residuals[i] < options.ransac_threshold_px) inlier_residuals.push_back(residuals[i]);
      }
      double threshold = options.ransac_threshold_px;
      if (options.refinement_inlier_sigmas > 0.0) {
        threshold = std::min(threshold,
                             options.refinement_inlier_sigmas * 1.4826 * Median(inlier_residuals));
      }
      std::vector<size_t> next;
      for (size_t i = 0; i < n; ++i) {
        if (residuals[i] < threshold) next.push_back(i);
      }
      if (next == subset || next.size() < 5) break;
      subset = std::move(next);
      refine_on(subset, options.refinement);
    }
    // The reported inliers are those of the refined model at RANSAC's threshold.
    const Eigen::Matrix3d E_refined = EssentialFromMotion(R, t);
    inliers.clear();
    for (size_t i = 0; i < n; ++i) {
      if (std::abs(SampsonErrorPx(E_refined, prev_norm[i], cur_norm[i], focal)) <
          options.ransac_threshold_px) {
        inliers.push_back(i);
      }
    }
    motion.refined_sampson_rms_px = rms_of(E_refined, inliers);
  }

  motion.rotation = R;
  motion.direction = t;
  set_inliers(inliers);
  motion.parallax_px = MedianParallaxPx(correspondences, camera, R, inliers);
  const bool enough =
      motion.num_inliers >= options.min_inliers && motion.inlier_ratio >= options.min_inlier_ratio;
  motion.status = enough ? MotionStatus::kOk : MotionStatus::kTooFewInliers;
  return motion;
}

}  // namespace roadscale
