#include "roadscale/mapping/frame_localizer.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <ceres/loss_function.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "roadscale/mapping/pose_parameters.h"
#include "roadscale/mapping/reprojection_residual.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

struct Match {
  Eigen::Vector3d point;
  Eigen::Vector2d pixel;
};

Rigid3d RefinePose(const std::vector<Match>& matches, const PinholeCamera& camera,
                   const Rigid3d& initial, const FrameLocalizerOptions& options) {
  PoseParameters pose = ToPoseParameters(initial);
  ceres::Problem problem;
  for (const Match& match : matches) {
    problem.AddResidualBlock(PoseOnlyReprojectionResidual::Create(camera, match.pixel, match.point),
                             new ceres::CauchyLoss(options.loss_px), pose.data());
  }
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  return FromPoseParameters(pose);
}

std::vector<Match> Inliers(const std::vector<Match>& matches, const PinholeCamera& camera,
                           const Rigid3d& cam_from_world, double threshold_px) {
  std::vector<Match> inliers;
  for (const Match& match : matches) {
    const Eigen::Vector3d point_cam = cam_from_world * match.point;
    if (point_cam.z() > 0.0 && (camera.Project(point_cam) - match.pixel).norm() < threshold_px) {
      inliers.push_back(match);
    }
  }
  return inliers;
}

std::optional<Rigid3d> PnpRansac(const std::vector<Match>& matches, const PinholeCamera& camera,
                                 const FrameLocalizerOptions& options) {
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  for (const Match& match : matches) {
    object.emplace_back(match.point.x(), match.point.y(), match.point.z());
    image.emplace_back(match.pixel.x(), match.pixel.y());
  }
  cv::Mat K;
  cv::eigen2cv(camera.K(), K);
  cv::Mat rvec, tvec;
  // OpenCV's RANSAC draws from its own generator seeded with a constant: repeatable.
  if (!cv::solvePnPRansac(object, image, K, cv::noArray(), rvec, tvec, false,
                          options.ransac_iterations, options.inlier_threshold_px, 0.99,
                          cv::noArray(), cv::SOLVEPNP_EPNP)) {
    return std::nullopt;
  }
  cv::Mat rotation_cv;
  cv::Rodrigues(rvec, rotation_cv);
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  cv::cv2eigen(rotation_cv, rotation);
  cv::cv2eigen(tvec, translation);
  if (!rotation.allFinite() || !translation.allFinite()) return std::nullopt;
  return MakeRigid3d(rotation, translation);
}

}  // namespace

void FrameLocalizerOptions::Check() const {
  CheckOption(min_landmarks >= 6, "mapping.localization_min_landmarks",
              "must be >= 6 (a pose has six degrees of freedom)");
  CheckOption(loss_px > 0.0, "mapping.localization_loss_px", "must be > 0");
  CheckOption(max_iterations >= 1, "mapping.localization_max_iterations", "must be >= 1");
  CheckOption(inlier_threshold_px > 0.0, "mapping.localization_inlier_threshold_px", "must be > 0");
  CheckOption(min_inlier_ratio > 0.0 && min_inlier_ratio <= 1.0,
              "mapping.localization_min_inlier_ratio", "must be in (0, 1]");
  CheckOption(ransac_iterations >= 1, "mapping.localization_ransac_iterations", "must be >= 1");
  CheckOption(max_direction_change_deg > 0.0 && max_direction_change_deg <= 180.0,
              "mapping.localization_max_direction_deg", "must be in (0, 180] (180: no check)");
}

std::optional<double> AngleToTwoViewDirectionDeg(const Rigid3d& cur_from_prev,
                                                 const Eigen::Vector3d& two_view_direction) {
  const double length = cur_from_prev.translation().norm();
  if (!(length > 0.0) || !(two_view_direction.norm() > 0.0)) return std::nullopt;
  const double cosine = cur_from_prev.translation().dot(two_view_direction.normalized()) / length;
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI;
}

bool AgreesWithTwoViewDirection(const Rigid3d& cur_from_prev,
                                const Eigen::Vector3d& two_view_direction, double max_deg) {
  const std::optional<double> angle = AngleToTwoViewDirectionDeg(cur_from_prev, two_view_direction);
  return !angle || *angle <= max_deg;
}

FrameLocalization LocalizeFrame(const std::vector<TrackObservation>& observations,
                                const std::map<int64_t, Landmark>& landmarks,
                                const PinholeCamera& camera, const Rigid3d& initial_cam_from_world,
                                const FrameLocalizerOptions& options) {
  FrameLocalization result;
  std::vector<Match> matches;
  for (const TrackObservation& observation : observations) {
    const auto landmark = landmarks.find(observation.track_id);
    if (landmark != landmarks.end())
      matches.push_back({landmark->second.position, observation.pixel});
  }
  result.num_landmarks = static_cast<int>(matches.size());
  if (result.num_landmarks < options.min_landmarks) return result;

  // One point behind the predicted camera would fail the refinement's first evaluation, and
  // Ceres would leave the whole pose at the prediction; those points only join the RANSAC.
  std::vector<Match> in_front;
  for (const Match& match : matches) {
    if ((initial_cam_from_world * match.point).z() > kMinDepthInFront) in_front.push_back(match);
  }
  Rigid3d pose = RefinePose(in_front, camera, initial_cam_from_world, options);
  std::vector<Match> inliers = Inliers(matches, camera, pose, options.inlier_threshold_px);
  if (static_cast<double>(inliers.size()) < options.min_inlier_ratio * matches.size()) {
    const std::optional<Rigid3d> ransac = PnpRansac(matches, camera, options);
    if (!ransac) return result;
    result.used_ransac = true;
    inliers = Inliers(matches, camera, *ransac, options.inlier_threshold_px);
    if (static_cast<int>(inliers.size()) < options.min_landmarks) return result;
    pose = RefinePose(inliers, camera, *ransac, options);
    inliers = Inliers(matches, camera, pose, options.inlier_threshold_px);
  }
  result.num_inliers = static_cast<int>(inliers.size());
  result.cam_from_world = pose;
  result.ok = result.num_inliers >= options.min_landmarks && pose.matrix().allFinite();
  return result;
}

}  // namespace roadscale
