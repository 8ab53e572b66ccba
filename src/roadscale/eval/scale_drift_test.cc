#include "roadscale/eval/scale_drift.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// A curving drive: 1 m forward a step while turning 2 degrees about the camera's y axis.
Trajectory CurvingDrive(size_t num_poses) {
  Trajectory trajectory;
  Rigid3d world_from_cam = Rigid3d::Identity();
  const Rigid3d prev_from_cur = MakeRigid3d(
      Eigen::AngleAxisd(2.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix(),
      Eigen::Vector3d(0.05, 0.01, 1.0));
  for (size_t k = 0; k < num_poses; ++k) {
    if (k > 0) world_from_cam = world_from_cam * prev_from_cur;
    trajectory.world_from_cam.push_back(world_from_cam);
    trajectory.timestamps.push_back(0.1 * static_cast<double>(k));
  }
  return trajectory;
}

TEST(ScaleDrift, FactorsStartAtTheInitialScaleAndGrowWithTheSeededWalk) {
  ScaleDriftOptions options;
  const std::vector<double> factors = ScaleDriftFactors(201, options);
  ASSERT_EQ(factors.size(), 201u);
  EXPECT_DOUBLE_EQ(factors[0], 0.3);
  // exp(0.002 * 200) = 1.49; the walk's standard deviation after 200 steps is 0.028.
  EXPECT_NEAR(factors[200] / factors[0], 1.49, 0.15);
  for (size_t k = 1; k < factors.size(); ++k) {
    EXPECT_NEAR(std::log(factors[k] / factors[k - 1]), 0.002, 5 * 0.002) << k;
  }
  EXPECT_EQ(ScaleDriftFactors(201, options), factors);
  options.seed = 2;
  EXPECT_NE(ScaleDriftFactors(201, options), factors);
  options.random_walk_sigma = 0.0;
  EXPECT_NEAR(ScaleDriftFactors(201, options)[200], 0.3 * std::exp(0.4), 1e-12);
}

TEST(ScaleDrift, DistortionScalesEveryStepAndKeepsRotationsDirectionsAndTimes) {
  const Trajectory trajectory = CurvingDrive(50);
  const ScaleDriftOptions options;
  const Trajectory distorted = DistortTrajectoryScale(trajectory, options);
  const std::vector<double> factors = ScaleDriftFactors(50, options);
  ASSERT_EQ(distorted.size(), trajectory.size());
  EXPECT_EQ(distorted.timestamps, trajectory.timestamps);
  EXPECT_TRUE(distorted.world_from_cam[0].isApprox(trajectory.world_from_cam[0]));
  for (size_t k = 1; k < trajectory.size(); ++k) {
    const Rigid3d step = trajectory.world_from_cam[k - 1].inverse() * trajectory.world_from_cam[k];
    const Rigid3d distorted_step =
        distorted.world_from_cam[k - 1].inverse() * distorted.world_from_cam[k];
    EXPECT_TRUE(distorted_step.linear().isApprox(step.linear(), 1e-12)) << k;
    EXPECT_TRUE(
        distorted.world_from_cam[k].linear().isApprox(trajectory.world_from_cam[k].linear(), 1e-12))
        << k;
    EXPECT_TRUE(distorted_step.translation().isApprox(factors[k] * step.translation(), 1e-9)) << k;
  }
}

TEST(ScaleDrift, KeepsEveryNthPoseWithItsTimestamp) {
  const Trajectory trajectory = CurvingDrive(10);
  const Trajectory kept = KeepEveryNthPose(trajectory, 3);
  ASSERT_EQ(kept.size(), 4u);  // poses 0, 3, 6, 9
  EXPECT_DOUBLE_EQ(kept.timestamps[2], trajectory.timestamps[6]);
  EXPECT_TRUE(kept.world_from_cam[3].isApprox(trajectory.world_from_cam[9]));
  EXPECT_EQ(KeepEveryNthPose(trajectory, 1).size(), 10u);
  EXPECT_THROW(KeepEveryNthPose(trajectory, 0), Error);
}

TEST(ScaleDrift, RejectsInvalidOptions) {
  ScaleDriftOptions options;
  options.initial_scale = 0.0;
  EXPECT_THROW(options.Check(), Error);
  options = ScaleDriftOptions();
  options.random_walk_sigma = -1.0;
  EXPECT_THROW(DistortTrajectoryScale(CurvingDrive(3), options), Error);
}

}  // namespace
}  // namespace roadscale
