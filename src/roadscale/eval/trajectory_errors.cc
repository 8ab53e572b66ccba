#include "roadscale/eval/trajectory_errors.h"

#include <cmath>
#include <string>

#include "roadscale/geometry/angles.h"
#include "roadscale/geometry/umeyama.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

Eigen::Matrix3Xd Positions(const std::vector<Rigid3d>& world_from_cam) {
  Eigen::Matrix3Xd positions(3, world_from_cam.size());
  for (size_t i = 0; i < world_from_cam.size(); ++i) {
    positions.col(static_cast<Eigen::Index>(i)) = world_from_cam[i].translation();
  }
  return positions;
}

double PositionRmse(const Eigen::Matrix3Xd& gt, const Eigen::Matrix3Xd& est) {
  return std::sqrt((gt - est).colwise().squaredNorm().mean());
}

double AlignedRmse(const Eigen::Matrix3Xd& gt, const Eigen::Matrix3Xd& est,
                   const Similarity3d& gt_from_est) {
  const Eigen::Matrix3Xd aligned =
      (gt_from_est.scale * gt_from_est.rotation * est).colwise() + gt_from_est.translation;
  return PositionRmse(gt, aligned);
}

}  // namespace

double PathLength(const std::vector<Rigid3d>& world_from_cam) {
  double length = 0.0;
  for (size_t i = 1; i < world_from_cam.size(); ++i) {
    length += (world_from_cam[i].translation() - world_from_cam[i - 1].translation()).norm();
  }
  return length;
}

TrajectoryErrors ComputeTrajectoryErrors(const std::vector<Rigid3d>& gt_world_from_cam,
                                         const std::vector<Rigid3d>& est_world_from_cam) {
  if (gt_world_from_cam.size() != est_world_from_cam.size()) {
    throw Error("trajectory errors need one estimated pose per ground-truth pose: got " +
                std::to_string(est_world_from_cam.size()) + " estimated and " +
                std::to_string(gt_world_from_cam.size()) + " ground-truth poses");
  }
  if (gt_world_from_cam.size() < 2) {
    throw Error("trajectory errors need at least 2 poses, got " +
                std::to_string(gt_world_from_cam.size()));
  }

  TrajectoryErrors errors;
  const Eigen::Matrix3Xd gt = Positions(gt_world_from_cam);
  const Eigen::Matrix3Xd est = Positions(est_world_from_cam);
  errors.ate_none_m = PositionRmse(gt, est);
  errors.ate_se3_m = AlignedRmse(gt, est, UmeyamaAlignment(est, gt, /*with_scale=*/false));
  const Eigen::Vector3d est_centre = est.rowwise().mean();
  if ((est.colwise() - est_centre).squaredNorm() > 0.0) {
    const Similarity3d gt_from_est = UmeyamaAlignment(est, gt, /*with_scale=*/true);
    errors.ate_sim3_m = AlignedRmse(gt, est, gt_from_est);
    errors.sim3_scale = gt_from_est.scale;
  }

  double trans_sum = 0.0;
  double rot_sum = 0.0;
  for (size_t i = 0; i + 1 < gt_world_from_cam.size(); ++i) {
    const Rigid3d gt_step = gt_world_from_cam[i].inverse() * gt_world_from_cam[i + 1];
    const Rigid3d est_step = est_world_from_cam[i].inverse() * est_world_from_cam[i + 1];
    const Rigid3d error = gt_step.inverse() * est_step;
    trans_sum += error.translation().squaredNorm();
    const double angle_deg = RotationAngle(error.linear()) * kDegreesPerRadian;
    rot_sum += angle_deg * angle_deg;
  }
  const double n_steps = static_cast<double>(gt_world_from_cam.size() - 1);
  errors.rpe_trans_rmse_m = std::sqrt(trans_sum / n_steps);
  errors.rpe_rot_rmse_deg = std::sqrt(rot_sum / n_steps);

  errors.gt_path_length_m = PathLength(gt_world_from_cam);
  errors.est_path_length_m = PathLength(est_world_from_cam);
  errors.final_drift_m = (gt.col(gt.cols() - 1) - est.col(est.cols() - 1)).norm();
  if (errors.gt_path_length_m > 0.0) {
    errors.length_ratio = errors.est_path_length_m / errors.gt_path_length_m;
    errors.final_drift_pct = 100.0 * errors.final_drift_m / errors.gt_path_length_m;
  }
  return errors;
}

}  // namespace roadscale
