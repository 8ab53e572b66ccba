#include "roadscale/mapping/road_pair_residual.h"

#include <gtest/gtest.h>

#include "roadscale/mapping/pose_parameters.h"

namespace roadscale {
namespace {

double PairResidual(const Rigid3d& anchor_cam_from_world, const Rigid3d& cam_from_world,
                    double height_per_baseline, double h0, double sigma) {
  const PoseParameters anchor = ToPoseParameters(anchor_cam_from_world);
  const PoseParameters pose = ToPoseParameters(cam_from_world);
  const RoadPairResidual residual(height_per_baseline, h0, sigma);
  double value = 0.0;
  EXPECT_TRUE(residual(anchor.data(), pose.data(), &value));
  return value;
}

// A camera at `centre` in the world, turned by `yaw` about its y axis.
Rigid3d CameraAt(const Eigen::Vector3d& centre, double yaw) {
  const Eigen::Matrix3d world_from_cam = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).matrix();
  return MakeRigid3d(world_from_cam.transpose(), -(world_from_cam.transpose() * centre));
}

TEST(RoadPairResidual, ZeroWhenTheBaselineTimesTheMeasuredRatioIsH0) {
  // The alignment measured h / |t| = 1.65 / 1.2; the cameras are 1.2 m apart.
  const Rigid3d anchor = CameraAt({3.0, -1.0, 10.0}, 0.2);
  const Rigid3d cur = CameraAt({3.0, -1.0, 11.2}, 0.25);
  EXPECT_NEAR(PairResidual(anchor, cur, 1.65 / 1.2, 1.65, 0.02), 0.0, 1e-12);
}

TEST(RoadPairResidual, CountsSigmasOfTheImpliedCameraHeight) {
  // The map's baseline 1.0 m where the road said 1.2 m: the implied height is 1.65 / 1.2 m,
  // (1.375 - 1.65) / 0.05 = -5.5 sigmas; twice the baseline gives +0.725 m, 14.5 sigmas.
  const Rigid3d anchor = CameraAt({0.0, 0.0, 0.0}, 0.0);
  EXPECT_NEAR(PairResidual(anchor, CameraAt({0.0, 0.0, 1.0}, 0.0), 1.65 / 1.2, 1.65, 0.05), -5.5,
              1e-9);
  EXPECT_NEAR(PairResidual(anchor, CameraAt({0.0, 0.0, 2.0}, 0.0), 1.65 / 1.2, 1.65, 0.05),
              (2.0 * 1.65 / 1.2 - 1.65) / 0.05, 1e-9);
}

TEST(RoadPairResidual, DependsOnTheCentresOnlyNotOnTheTurns) {
  // The term scales the map; the directions are the reprojection's business.
  const double straight =
      PairResidual(CameraAt({1.0, 0.0, 0.0}, 0.0), CameraAt({1.0, 0.0, 1.5}, 0.0), 1.2, 1.65, 0.02);
  const double turned = PairResidual(CameraAt({1.0, 0.0, 0.0}, 0.4),
                                     CameraAt({1.0, 0.0, 1.5}, -0.3), 1.2, 1.65, 0.02);
  EXPECT_NEAR(straight, turned, 1e-9);
  EXPECT_NEAR(straight, (1.2 * 1.5 - 1.65) / 0.02, 1e-9);
}

}  // namespace
}  // namespace roadscale
