#include "roadscale/mapping/camera_height_residual.h"

#include <gtest/gtest.h>

#include "roadscale/mapping/pose_parameters.h"

namespace roadscale {
namespace {

double HeightResidual(const Rigid3d& cam_from_world, const Eigen::Vector3d& point,
                      const Eigen::Vector3d& normal, double h0, double sigma) {
  const PoseParameters pose = ToPoseParameters(cam_from_world);
  const CameraHeightResidual residual(normal, h0, sigma);
  double value = 0.0;
  EXPECT_TRUE(residual(pose.data(), point.data(), &value));
  return value;
}

TEST(CameraHeightResidual, ZeroForAPointOnTheRoadH0BelowTheCamera) {
  const Rigid3d cam_from_world = Rigid3d::Identity();
  EXPECT_NEAR(
      HeightResidual(cam_from_world, {2.0, 1.65, 9.0}, Eigen::Vector3d::UnitY(), 1.65, 0.05), 0.0,
      1e-12);
}

TEST(CameraHeightResidual, CountsSigmasAndIsPositiveBelowTheRoad) {
  // 10 cm below the road plane, sigma 5 cm: +2; 10 cm above: -2.
  EXPECT_NEAR(
      HeightResidual(Rigid3d::Identity(), {0.0, 1.75, 5.0}, Eigen::Vector3d::UnitY(), 1.65, 0.05),
      2.0, 1e-9);
  EXPECT_NEAR(
      HeightResidual(Rigid3d::Identity(), {0.0, 1.55, 5.0}, Eigen::Vector3d::UnitY(), 1.65, 0.05),
      -2.0, 1e-9);
}

TEST(CameraHeightResidual, MeasuresInTheAnchorCameraAlongItsNormal) {
  // A camera 3 m up the world's y-down axis (centre at y = -3) and pitched: the point is
  // h0 below it along the pitched normal.
  const double pitch = 4.0 * M_PI / 180.0;
  const Eigen::Matrix3d world_from_cam_rotation =
      Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Rigid3d world_from_cam =
      MakeRigid3d(world_from_cam_rotation, Eigen::Vector3d(0.0, -3.0, 10.0));
  const Eigen::Vector3d normal_cam(0.0, std::cos(0.1), std::sin(0.1));
  const Eigen::Vector3d point_cam =
      1.65 * normal_cam + Eigen::Vector3d(1.0, 0.0, 0.0).cross(normal_cam) * 6.0;
  const Eigen::Vector3d point_world = world_from_cam * point_cam;
  EXPECT_NEAR(HeightResidual(world_from_cam.inverse(), point_world, normal_cam, 1.65, 0.05), 0.0,
              1e-9);
  // Twice the map's scale doubles the height: +h0 / sigma.
  EXPECT_NEAR(HeightResidual(world_from_cam.inverse(), world_from_cam * (2.0 * point_cam),
                             normal_cam, 1.65, 0.05),
              1.65 / 0.05, 1e-9);
}

}  // namespace
}  // namespace roadscale
