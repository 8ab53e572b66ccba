#include "roadscale/pipeline/pose_integrator.h"

#include <gtest/gtest.h>

namespace roadscale {
namespace {

TwoViewMotion Motion(MotionStatus status, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  TwoViewMotion motion;
  motion.status = status;
  motion.rotation = R;
  motion.direction = t;
  return motion;
}

ScaleResult Length(double metres) {
  ScaleResult scale;
  scale.valid = true;
  scale.step_length_m = metres;
  return scale;
}

const Eigen::Matrix3d kIdentity = Eigen::Matrix3d::Identity();
const Eigen::Vector3d kZero = Eigen::Vector3d::Zero();

TEST(PoseIntegrator, ChainsInverseStepsFromTheFirstFrame) {
  PoseIntegrator integrator;
  EXPECT_EQ(integrator.Apply(Motion(MotionStatus::kFirstFrame, kIdentity, kZero), {}),
            PoseUpdate::kFirst);
  EXPECT_TRUE(integrator.world_from_cam().isApprox(Rigid3d::Identity()));

  // Driving forward 2 m: the scene moves towards the camera, cur_from_prev t = (0, 0, -1).
  EXPECT_EQ(integrator.Apply(Motion(MotionStatus::kOk, kIdentity, {0, 0, -1}), Length(2.0)),
            PoseUpdate::kMotion);
  EXPECT_TRUE(integrator.world_from_cam().translation().isApprox(Eigen::Vector3d(0, 0, 2)));
  EXPECT_DOUBLE_EQ(integrator.step_length(), 2.0);

  // Turn 90 degrees left (about -y in KITTI's frame, y down) and drive 1 m.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix().transpose();
  const Eigen::Vector3d t = -turn * Eigen::Vector3d(0, 0, 1);
  integrator.Apply(Motion(MotionStatus::kOk, turn, t), Length(1.0));
  const Rigid3d expected =
      MakeRigid3d(Eigen::Matrix3d::Identity(), {0, 0, 2}) * MakeRigid3d(turn, t).inverse();
  EXPECT_TRUE(integrator.world_from_cam().isApprox(expected, 1e-12));
}

TEST(PoseIntegrator, KeepsThePoseWhenStationary) {
  PoseIntegrator integrator;
  integrator.Apply(Motion(MotionStatus::kFirstFrame, kIdentity, kZero), {});
  integrator.Apply(Motion(MotionStatus::kOk, kIdentity, {0, 0, -1}), Length(1.0));
  const Rigid3d before = integrator.world_from_cam();
  EXPECT_EQ(integrator.Apply(Motion(MotionStatus::kStationary, kIdentity, kZero), Length(0.01)),
            PoseUpdate::kKept);
  EXPECT_TRUE(integrator.world_from_cam().isApprox(before));
  EXPECT_EQ(integrator.step_length(), 0.0);
}

TEST(PoseIntegrator, PureRotationKeepsTheLastDirection) {
  PoseIntegrator integrator;
  integrator.Apply(Motion(MotionStatus::kFirstFrame, kIdentity, kZero), {});
  const Eigen::Vector3d direction = Eigen::Vector3d(0.1, 0.0, -1.0).normalized();
  integrator.Apply(Motion(MotionStatus::kOk, kIdentity, direction), Length(1.0));
  const Rigid3d before = integrator.world_from_cam();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_EQ(integrator.Apply(Motion(MotionStatus::kPureRotation, R, Eigen::Vector3d::Zero()),
                             Length(0.5)),
            PoseUpdate::kRotationOnly);
  EXPECT_TRUE(integrator.cur_from_prev().linear().isApprox(R));
  EXPECT_TRUE(integrator.cur_from_prev().translation().isApprox(0.5 * direction));
  EXPECT_TRUE(
      integrator.world_from_cam().isApprox(before * MakeRigid3d(R, 0.5 * direction).inverse()));
}

TEST(PoseIntegrator, PureRotationWithoutALengthShrinksTheLastOneByTheParallax) {
  PoseIntegrator integrator;
  integrator.Apply(Motion(MotionStatus::kFirstFrame, kIdentity, kZero), {});
  TwoViewMotion moving = Motion(MotionStatus::kOk, kIdentity, {0, 0, -1});
  moving.parallax_px = 4.0;
  integrator.Apply(moving, Length(0.8));
  TwoViewMotion creeping = Motion(MotionStatus::kPureRotation, kIdentity, kZero);
  creeping.parallax_px = 0.5;
  EXPECT_EQ(integrator.Apply(creeping, ScaleResult()), PoseUpdate::kRotationOnly);
  EXPECT_NEAR(integrator.step_length(), 0.8 * 0.5 / 4.0, 1e-12);
  // Never longer than the last length, and the last length stays for the next frames.
  creeping.parallax_px = 9.0;
  integrator.Apply(creeping, ScaleResult());
  EXPECT_NEAR(integrator.step_length(), 0.8, 1e-12);
  integrator.Apply(Motion(MotionStatus::kTooFewTracks, kIdentity, kZero), ScaleResult());
  EXPECT_NEAR(integrator.step_length(), 0.8, 1e-12);
}

TEST(PoseIntegrator, ParallaxScaledLength) {
  EXPECT_DOUBLE_EQ(ParallaxScaledLength(2.0, 1.0, 4.0), 0.5);
  EXPECT_DOUBLE_EQ(ParallaxScaledLength(2.0, 8.0, 4.0), 4.0);
  EXPECT_DOUBLE_EQ(ParallaxScaledLength(2.0, 0.0, 4.0), 2.0);
  EXPECT_DOUBLE_EQ(ParallaxScaledLength(2.0, 1.0, 0.0), 2.0);
}

TEST(PoseIntegrator, RepeatsTheLastStepWithoutAnEstimateAndKeepsTheLastLength) {
  PoseIntegrator integrator;
  integrator.Apply(Motion(MotionStatus::kFirstFrame, kIdentity, kZero), {});
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitY()).toRotationMatrix();
  integrator.Apply(Motion(MotionStatus::kOk, R, {0, 0, -1}), Length(0.8));
  EXPECT_EQ(integrator.Apply(Motion(MotionStatus::kTooFewInliers, kIdentity, kZero), ScaleResult()),
            PoseUpdate::kConstantVelocity);
  EXPECT_TRUE(integrator.cur_from_prev().linear().isApprox(R));
  EXPECT_TRUE(integrator.cur_from_prev().translation().isApprox(Eigen::Vector3d(0, 0, -0.8)));
  EXPECT_EQ(integrator.Apply(Motion(MotionStatus::kTooFewTracks, kIdentity, kZero), Length(0.6)),
            PoseUpdate::kConstantVelocity);
  EXPECT_DOUBLE_EQ(integrator.step_length(), 0.6);
}

TEST(PoseIntegrator, NothingMovesBeforeTheFirstEstimate) {
  PoseIntegrator integrator;
  integrator.Apply(Motion(MotionStatus::kFirstFrame, kIdentity, kZero), {});
  integrator.Apply(Motion(MotionStatus::kTooFewTracks, kIdentity, kZero), Length(1.0));
  EXPECT_TRUE(integrator.world_from_cam().isApprox(Rigid3d::Identity()));
}

TEST(PoseIntegrator, StepsHaveUnitLengthUntilTheFirstValidScale) {
  PoseIntegrator integrator;
  integrator.Apply(Motion(MotionStatus::kFirstFrame, kIdentity, kZero), {});
  const Eigen::Vector3d forward = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(integrator.Apply(Motion(MotionStatus::kOk, kIdentity, -forward), ScaleResult()),
            PoseUpdate::kMotion);
  EXPECT_FALSE(integrator.has_scale());
  EXPECT_NEAR(integrator.step_length(), 1.0, 1e-12);
  integrator.Apply(Motion(MotionStatus::kOk, kIdentity, -forward), Length(0.25));
  EXPECT_TRUE(integrator.has_scale());
  EXPECT_NEAR(integrator.step_length(), 0.25, 1e-12);
  EXPECT_NEAR(integrator.world_from_cam().translation().z(), 1.25, 1e-12);
}

}  // namespace
}  // namespace roadscale
