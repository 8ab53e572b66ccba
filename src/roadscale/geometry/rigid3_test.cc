#include "roadscale/geometry/rigid3.h"

#include <cmath>

#include <gtest/gtest.h>

namespace roadscale {
namespace {

TEST(Rigid3, CompositionReadsRightToLeft) {
  const Rigid3d world_from_prev =
      MakeRigid3d(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix(),
                  Eigen::Vector3d(1, 2, 3));
  const Rigid3d prev_from_cur = MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 1));
  const Rigid3d world_from_cur = world_from_prev * prev_from_cur;
  const Eigen::Vector3d origin_of_cur = world_from_cur * Eigen::Vector3d::Zero();
  EXPECT_TRUE(origin_of_cur.isApprox(Eigen::Vector3d(1 + std::sin(0.3), 2, 3 + std::cos(0.3))));
}

TEST(Rigid3, RotationAngleSmallAndLarge) {
  for (double angle : {0.0, 1e-9, 1e-4, 0.5, 3.0, M_PI - 1e-6}) {
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    EXPECT_NEAR(RotationAngle(rotation), angle, 1e-9) << angle;
  }
}

TEST(Rigid3, NearestRotationRepairsRoundedMatrix) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  Eigen::Matrix3d rounded = rotation;
  rounded(0, 1) += 1e-4;
  const Eigen::Matrix3d repaired = NearestRotation(rounded);
  EXPECT_NEAR(repaired.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((repaired * repaired.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_LT((repaired - rotation).norm(), 1e-4);
}

TEST(Rigid3, SkewMatrixIsTheCrossProduct) {
  const Eigen::Vector3d v(0.3, -1.2, 2.0);
  const Eigen::Vector3d u(-0.7, 0.4, 1.1);
  EXPECT_TRUE((SkewMatrix(v) * u).isApprox(v.cross(u)));
}

TEST(Rigid3, ExpSo3TurnsAboutTheAxis) {
  const Eigen::Vector3d omega = 0.2 * Eigen::Vector3d(1.0, 2.0, -2.0).normalized();
  EXPECT_TRUE(
      ExpSo3(omega).isApprox(Eigen::AngleAxisd(0.2, omega.normalized()).toRotationMatrix()));
  EXPECT_TRUE(ExpSo3(Eigen::Vector3d::Zero()).isApprox(Eigen::Matrix3d::Identity()));
  EXPECT_NEAR(RotationAngle(ExpSo3(Eigen::Vector3d(1e-9, 0.0, 0.0))), 1e-9, 1e-15);
}

}  // namespace
}  // namespace roadscale
