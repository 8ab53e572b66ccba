#include "roadscale/mapping/two_row_residual.h"

#include <memory>

#include <ceres/loss_function.h>

#include <gtest/gtest.h>

#include "roadscale/mapping/camera_height_residual.h"

namespace roadscale {
namespace {

TEST(TwoRowResidual, KeepsTheOneRowResidualAndJacobianAndAddsAZeroRow) {
  const Eigen::Vector3d normal = Eigen::Vector3d(0.02, 1.0, -0.05).normalized();
  const std::unique_ptr<ceres::CostFunction> one_row(
      CameraHeightResidual::Create(normal, 1.65, 0.05));
  const TwoRowResidual two_rows(CameraHeightResidual::Create(normal, 1.65, 0.05));
  EXPECT_EQ(two_rows.num_residuals(), 2);

  const double pose[6] = {0.01, -0.2, 0.03, 0.4, -1.2, 3.0};
  const double point[3] = {1.5, 1.8, 12.0};
  const double* parameters[2] = {pose, point};
  double expected_residual = 0.0;
  double expected_pose[6];
  double expected_point[3];
  double* expected_jacobians[2] = {expected_pose, expected_point};
  ASSERT_TRUE(one_row->Evaluate(parameters, &expected_residual, expected_jacobians));

  double residual[2] = {-1.0, -1.0};
  double pose_jacobian[12];
  double point_jacobian[6];
  std::fill(pose_jacobian, pose_jacobian + 12, -1.0);
  std::fill(point_jacobian, point_jacobian + 6, -1.0);
  double* jacobians[2] = {pose_jacobian, point_jacobian};
  ASSERT_TRUE(two_rows.Evaluate(parameters, residual, jacobians));
  EXPECT_EQ(residual[0], expected_residual);
  EXPECT_EQ(residual[1], 0.0);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(pose_jacobian[i], expected_pose[i]);
    EXPECT_EQ(pose_jacobian[6 + i], 0.0);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(point_jacobian[i], expected_point[i]);
    EXPECT_EQ(point_jacobian[3 + i], 0.0);
  }

  // Without Jacobians, and with the pose held constant (no pose Jacobian asked for).
  double* only_point[2] = {nullptr, point_jacobian};
  ASSERT_TRUE(two_rows.Evaluate(parameters, residual, nullptr));
  EXPECT_EQ(residual[0], expected_residual);
  ASSERT_TRUE(two_rows.Evaluate(parameters, residual, only_point));
  EXPECT_EQ(point_jacobian[0], expected_point[0]);

  // The robust loss sees the same squared norm, so the cost is the same.
  const ceres::HuberLoss loss(1.0);
  double rho_one[3];
  double rho_two[3];
  loss.Evaluate(expected_residual * expected_residual, rho_one);
  loss.Evaluate(residual[0] * residual[0] + residual[1] * residual[1], rho_two);
  EXPECT_EQ(rho_one[0], rho_two[0]);
}

}  // namespace
}  // namespace roadscale
