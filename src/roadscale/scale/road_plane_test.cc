#include "roadscale/scale/road_plane.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/geometry/angles.h"

namespace roadscale {
namespace {

// A camera pitched down by `pitch_rad` above a level road: level_from_cam.
Eigen::Matrix3d PitchedDown(double pitch_rad) {
  return Eigen::AngleAxisd(-pitch_rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

TEST(RoadPlane, PitchedCameraSeesRisingRoadWithPositivePitch) {
  for (double pitch_deg : {-5.0, 5.0}) {
    const Eigen::Matrix3d level_from_cam = PitchedDown(pitch_deg * kRadiansPerDegree);
    // Its optical axis points below the horizon when pitched down (y is down).
    EXPECT_EQ((level_from_cam * Eigen::Vector3d::UnitZ()).y() > 0.0, pitch_deg > 0.0);
    const auto cam = [&](const Eigen::Vector3d& level) {
      return Eigen::Vector3d(level_from_cam.transpose() * level);
    };
    const std::optional<Plane> plane = PlaneThroughPoints(
        cam({0, 1.65, 5}), cam({2, 1.65, 20}), cam({-3, 1.65, 9}), Eigen::Vector3d::UnitY());
    ASSERT_TRUE(plane.has_value());
    EXPECT_NEAR(plane->height, 1.65, 1e-12);
    EXPECT_NEAR(plane->PitchRad(), pitch_deg * kRadiansPerDegree, 1e-12);
    EXPECT_NEAR(plane->RollRad(), 0.0, 1e-12);
    EXPECT_TRUE(
        plane->normal.isApprox(RoadNormalFromCameraPitch(pitch_deg * kRadiansPerDegree), 1e-12));
    // Driving straight ahead on that road implies the same normal.
    const Rigid3d prev_from_cur = MakeRigid3d(Eigen::Matrix3d::Identity(), cam({0, 0, 1.2}));
    const std::optional<Eigen::Vector3d> from_motion =
        RoadNormalFromMotion(prev_from_cur.inverse());
    ASSERT_TRUE(from_motion.has_value());
    EXPECT_TRUE(from_motion->isApprox(plane->normal, 1e-12));
  }
}

TEST(RoadPlane, MotionOfKnownGradeImpliesRoadNormal) {
  for (double grade_deg : {-5.0, 5.0}) {
    // A level camera driving up (grade > 0) or down a slope: the travel direction rises
    // (y decreases) uphill.
    const Eigen::Vector3d travel(0.0, -std::sin(grade_deg * kRadiansPerDegree),
                                 std::cos(grade_deg * kRadiansPerDegree));
    const Rigid3d cur_from_prev = MakeRigid3d(Eigen::Matrix3d::Identity(), -0.9 * travel);
    const std::optional<Eigen::Vector3d> direction = TravelDirection(cur_from_prev);
    ASSERT_TRUE(direction.has_value());
    EXPECT_TRUE(direction->isApprox(travel, 1e-12));
    const std::optional<Eigen::Vector3d> normal = RoadNormalFromMotion(cur_from_prev);
    ASSERT_TRUE(normal.has_value());
    EXPECT_NEAR(normal->dot(travel), 0.0, 1e-12);
    EXPECT_GT(normal->y(), 0.0);
    EXPECT_NEAR(std::atan2(normal->z(), normal->y()), grade_deg * kRadiansPerDegree, 1e-12);
  }
}

TEST(RoadPlane, TravelDirectionAccountsForRotation) {
  // The current camera is 1 m to the right of and 2 m ahead of the previous one, turned.
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Rigid3d prev_from_cur = MakeRigid3d(turn, Eigen::Vector3d(1, 0, 2));
  const std::optional<Eigen::Vector3d> direction = TravelDirection(prev_from_cur.inverse());
  ASSERT_TRUE(direction.has_value());
  EXPECT_TRUE(direction->isApprox(Eigen::Vector3d(1, 0, 2).normalized(), 1e-12));
}

TEST(RoadPlane, NoMotionOrVerticalMotionImpliesNoRoad) {
  EXPECT_FALSE(TravelDirection(Rigid3d::Identity()).has_value());
  EXPECT_FALSE(RoadNormalFromMotion(Rigid3d::Identity()).has_value());
  const Rigid3d upwards = MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 1, 0));
  EXPECT_FALSE(RoadNormalFromMotion(upwards).has_value());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(TravelDirection(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(nan, 0, 1)))
                   .has_value());
}

TEST(RoadPlane, CollinearPointsGiveNoPlane) {
  EXPECT_FALSE(
      PlaneThroughPoints({0, 1, 1}, {0, 1, 2}, {0, 1, 3}, Eigen::Vector3d::UnitY()).has_value());
}

TEST(RoadPlane, AngleBetweenIsPreciseForSmallAngles) {
  const Eigen::Vector3d a = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d b(0.0, std::cos(1e-8), std::sin(1e-8));
  EXPECT_NEAR(AngleBetween(a, b), 1e-8, 1e-20);
  EXPECT_NEAR(AngleBetween(a, -a), M_PI, 1e-15);
}

}  // namespace
}  // namespace roadscale
