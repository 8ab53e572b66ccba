#include "roadscale/eval/trajectory_errors.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/testing/test_trajectories.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::vector<Rigid3d> Transformed(const Rigid3d& new_world_from_world,
                                 const std::vector<Rigid3d>& world_from_cam) {
  std::vector<Rigid3d> result;
  for (const Rigid3d& pose : world_from_cam) result.push_back(new_world_from_world * pose);
  return result;
}

TEST(TrajectoryErrors, IdenticalTrajectoriesGiveZeros) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(400, 1.0);
  const TrajectoryErrors errors = ComputeTrajectoryErrors(gt, gt);
  EXPECT_EQ(errors.ate_none_m, 0.0);
  EXPECT_NEAR(errors.ate_se3_m, 0.0, 1e-9);
  ASSERT_TRUE(errors.ate_sim3_m && errors.sim3_scale);
  EXPECT_NEAR(*errors.ate_sim3_m, 0.0, 1e-9);
  EXPECT_NEAR(*errors.sim3_scale, 1.0, 1e-12);
  EXPECT_NEAR(errors.rpe_trans_rmse_m, 0.0, 1e-12);
  EXPECT_NEAR(errors.rpe_rot_rmse_deg, 0.0, 1e-9);
  ASSERT_TRUE(errors.length_ratio && errors.final_drift_pct);
  EXPECT_EQ(*errors.length_ratio, 1.0);
  EXPECT_EQ(errors.final_drift_m, 0.0);
  EXPECT_EQ(*errors.final_drift_pct, 0.0);
}

TEST(TrajectoryErrors, ShiftedTrajectoryHasNoneAteEqualToTheOffset) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(400, 1.0);
  const Eigen::Vector3d offset(3.0, -1.0, 2.0);
  const std::vector<Rigid3d> est =
      Transformed(MakeRigid3d(Eigen::Matrix3d::Identity(), offset), gt);
  const TrajectoryErrors errors = ComputeTrajectoryErrors(gt, est);
  EXPECT_NEAR(errors.ate_none_m, offset.norm(), 1e-12);
  EXPECT_NEAR(errors.ate_se3_m, 0.0, 1e-9);
  EXPECT_NEAR(*errors.ate_sim3_m, 0.0, 1e-9);
  EXPECT_NEAR(errors.final_drift_m, offset.norm(), 1e-12);
  EXPECT_NEAR(*errors.final_drift_pct, 100.0 * offset.norm() / errors.gt_path_length_m, 1e-12);
}

TEST(TrajectoryErrors, RigidlyMovedTrajectoryHasZeroSe3Ate) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(400, 1.0);
  const Rigid3d moved = MakeRigid3d(
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1.0, -0.3).normalized()).toRotationMatrix(),
      Eigen::Vector3d(10.0, -2.0, 5.0));
  const std::vector<Rigid3d> est = Transformed(moved, gt);
  const TrajectoryErrors errors = ComputeTrajectoryErrors(gt, est);
  double squared_sum = 0.0;
  for (size_t i = 0; i < gt.size(); ++i) {
    squared_sum += (est[i].translation() - gt[i].translation()).squaredNorm();
  }
  EXPECT_NEAR(errors.ate_none_m, std::sqrt(squared_sum / gt.size()), 1e-9);
  EXPECT_GT(errors.ate_none_m, 1.0);
  EXPECT_NEAR(errors.ate_se3_m, 0.0, 1e-9);
  EXPECT_NEAR(*errors.ate_sim3_m, 0.0, 1e-9);
  EXPECT_NEAR(*errors.sim3_scale, 1.0, 1e-12);
  // A change of world frame leaves frame-to-frame motion and path length unchanged.
  EXPECT_NEAR(errors.rpe_trans_rmse_m, 0.0, 1e-9);
  EXPECT_NEAR(errors.rpe_rot_rmse_deg, 0.0, 1e-6);
  EXPECT_NEAR(*errors.length_ratio, 1.0, 1e-12);
}

TEST(TrajectoryErrors, ScaledTrajectory) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(400, 1.0);
  std::vector<Rigid3d> est = gt;
  for (Rigid3d& pose : est) pose.translation() *= 1.25;
  const TrajectoryErrors errors = ComputeTrajectoryErrors(gt, est);
  ASSERT_TRUE(errors.sim3_scale && errors.ate_sim3_m && errors.length_ratio);
  EXPECT_NEAR(*errors.sim3_scale, 0.8, 1e-12);
  EXPECT_NEAR(*errors.ate_sim3_m, 0.0, 1e-9);
  EXPECT_NEAR(*errors.length_ratio, 1.25, 1e-12);
  EXPECT_GT(errors.ate_se3_m, 1.0);
  // Every step is 25 % too long: the per-frame translation error is a quarter of the step.
  double squared_sum = 0.0;
  for (size_t i = 0; i + 1 < gt.size(); ++i) {
    squared_sum += 0.0625 * (gt[i + 1].translation() - gt[i].translation()).squaredNorm();
  }
  EXPECT_NEAR(errors.rpe_trans_rmse_m, std::sqrt(squared_sum / (gt.size() - 1)), 1e-12);
  EXPECT_NEAR(errors.rpe_rot_rmse_deg, 0.0, 1e-6);
  EXPECT_NEAR(errors.final_drift_m, 0.25 * gt.back().translation().norm(), 1e-9);
}

TEST(TrajectoryErrors, RelativePoseErrorOfOneBadStep) {
  // Straight 1 m steps; the estimate's step 2 -> 3 is 0.5 m too long and turned by 2
  // degrees, after which it continues correctly from there.
  std::vector<Rigid3d> gt;
  for (int i = 0; i < 6; ++i) {
    gt.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i)));
  }
  std::vector<Rigid3d> est = {gt[0]};
  for (int i = 0; i < 5; ++i) {
    const Rigid3d step =
        i == 2 ? MakeRigid3d(Eigen::AngleAxisd(2.0 * M_PI / 180.0, Eigen::Vector3d::UnitY())
                                 .toRotationMatrix(),
                             Eigen::Vector3d(0, 0, 1.5))
               : gt[i].inverse() * gt[i + 1];
    est.push_back(est.back() * step);
  }
  const TrajectoryErrors errors = ComputeTrajectoryErrors(gt, est);
  // One of five steps is off by 0.5 m and 2 degrees.
  EXPECT_NEAR(errors.rpe_trans_rmse_m, std::sqrt(0.25 / 5.0), 1e-12);
  EXPECT_NEAR(errors.rpe_rot_rmse_deg, std::sqrt(4.0 / 5.0), 1e-9);
  EXPECT_NEAR(errors.gt_path_length_m, 5.0, 1e-12);
  EXPECT_NEAR(errors.est_path_length_m, 5.5, 1e-12);
  EXPECT_NEAR(*errors.length_ratio, 1.1, 1e-12);
}

TEST(TrajectoryErrors, StationaryTrajectoriesGiveEmptyRatios) {
  const std::vector<Rigid3d> still(5, Rigid3d::Identity());
  const TrajectoryErrors errors = ComputeTrajectoryErrors(still, still);
  EXPECT_FALSE(errors.ate_sim3_m);
  EXPECT_FALSE(errors.sim3_scale);
  EXPECT_FALSE(errors.length_ratio);
  EXPECT_FALSE(errors.final_drift_pct);
  EXPECT_EQ(errors.ate_none_m, 0.0);
}

TEST(TrajectoryErrors, RejectsMismatchedOrTooShortInput) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(10, 1.0);
  EXPECT_THROW(ComputeTrajectoryErrors(gt, {gt.begin(), gt.end() - 1}), Error);
  EXPECT_THROW(ComputeTrajectoryErrors({gt[0]}, {gt[0]}), Error);
}

}  // namespace
}  // namespace roadscale
