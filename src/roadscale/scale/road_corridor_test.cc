#include "roadscale/scale/road_corridor.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/scale/road_plane.h"
#include "roadscale/scale/synthetic_road_scene.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(RoadCorridor, FootprintOfARoadPointIsItsPositionOnALevelRoad) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Eigen::Vector3d down = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d forward = Eigen::Vector3d::UnitZ();
  for (const Eigen::Vector3d& point :
       {Eigen::Vector3d(2.0, 1.65, 10.0), Eigen::Vector3d(-3.5, 1.65, 6.0),
        Eigen::Vector3d(0.3, 1.65, 25.0)}) {
    const RoadFootprint footprint =
        FootprintOnRoad(camera.Project(point), camera, down, forward, 1.65);
    ASSERT_TRUE(footprint.valid);
    EXPECT_NEAR(footprint.ahead, point.z(), 1e-9);
    EXPECT_NEAR(footprint.lateral, point.x(), 1e-9);
  }
  // Above the horizon the ray never meets the road.
  EXPECT_FALSE(
      FootprintOnRoad(camera.Project(Eigen::Vector3d(0.0, -1.0, 10.0)), camera, down, forward, 1.65)
          .valid);
}

TEST(RoadCorridor, FootprintOnAPitchedRoadUsesTheRoadFrame) {
  // A road pitched by 3 degrees (rising ahead): its own axes give the point's place on it.
  const PinholeCamera camera = KittiOdometryCamera();
  const double pitch = 3.0 * kDeg;
  const Plane road{Eigen::Vector3d(0.0, std::cos(pitch), std::sin(pitch)), 1.65};
  const Eigen::Vector3d along(0.0, -std::sin(pitch), std::cos(pitch));
  const Eigen::Vector3d point =
      road.height * road.normal + 12.0 * along + 1.5 * Eigen::Vector3d::UnitX();
  const RoadFootprint footprint =
      FootprintOnRoad(camera.Project(point), camera, road.normal, along, road.height);
  ASSERT_TRUE(footprint.valid);
  EXPECT_NEAR(footprint.ahead, 12.0, 1e-9);
  EXPECT_NEAR(footprint.lateral, 1.5, 1e-9);
}

TEST(RoadCorridor, YawIsTheTurnAboutTheRoadNormalRightPositive) {
  const Plane road{Eigen::Vector3d(0.0, std::cos(2 * kDeg), std::sin(2 * kDeg)), 1.65};
  for (double yaw : {-3.0 * kDeg, 0.0, 0.5 * kDeg, 4.0 * kDeg}) {
    const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, yaw);
    EXPECT_NEAR(YawAboutRoadNormal(motion, road.normal), yaw, 1e-12);
  }
  // A right turn: the current camera looks towards +x of the previous one.
  const Rigid3d right = testing::DriveAlongRoad(road, 1.0, 2.0 * kDeg);
  EXPECT_GT((right.linear().transpose() * Eigen::Vector3d::UnitZ()).x(), 0.0);
}

// Pixels of road points on a grid: lateral -6..6 m, ahead 2..40 m, every metre.
std::vector<Eigen::Vector2d> GridPixels(const PinholeCamera& camera,
                                        std::vector<Eigen::Vector3d>* points) {
  std::vector<Eigen::Vector2d> pixels;
  for (int x = -6; x <= 6; ++x) {
    for (int z = 2; z <= 40; ++z) {
      const Eigen::Vector3d point(x + 0.25, 1.65, z + 0.5);
      const Eigen::Vector2d pixel = camera.Project(point);
      if (!camera.IsInside(pixel)) continue;
      pixels.push_back(pixel);
      points->push_back(point);
    }
  }
  return pixels;
}

TEST(RoadCorridor, StraightCorridorKeepsExactlyThePointsWithinWidthAndDistance) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  std::vector<Eigen::Vector3d> points;
  const std::vector<Eigen::Vector2d> pixels = GridPixels(camera, &points);
  RoadCorridorOptions options;
  options.enabled = true;
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, 0.0);
  const std::vector<int> kept =
      SelectRoadCorridor(pixels, camera, motion, road.normal, 1.65, 1.0, options);
  std::vector<int> expected;
  for (size_t i = 0; i < points.size(); ++i) {
    if (std::abs(points[i].x()) <= 3.0 && points[i].z() <= 20.0) {
      expected.push_back(static_cast<int>(i));
    }
  }
  EXPECT_EQ(kept, expected);
  EXPECT_GT(kept.size(), 50U);
}

TEST(RoadCorridor, TurningCorridorFollowsTheArc) {
  // A right turn of 2 degrees a metre: radius 28.6 m. 15 m ahead the path lies
  // k s^2 / 2 - yaw s / 2 = 3.91 m - 0.26 m = 3.65 m to the right of the travel line.
  const PinholeCamera camera = KittiOdometryCamera();
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const double yaw = 2.0 * kDeg;
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, yaw);
  const std::optional<Eigen::Vector3d> travel = TravelDirection(motion);
  ASSERT_TRUE(travel);
  const Eigen::Vector3d lateral = road.normal.cross(*travel);
  const double s = 15.0;
  const double path = 0.5 * (yaw / 1.0) * s * s - 0.5 * yaw * s;
  const Eigen::Vector3d foot = road.height * road.normal;
  const Eigen::Vector3d on_path = foot + s * *travel + path * lateral;
  const Eigen::Vector3d on_line = foot + s * *travel - 0.2 * lateral;
  const std::vector<Eigen::Vector2d> pixels = {camera.Project(on_path), camera.Project(on_line)};
  RoadCorridorOptions options;
  options.enabled = true;
  EXPECT_EQ(SelectRoadCorridor(pixels, camera, motion, road.normal, 1.65, 1.0, options),
            std::vector<int>({0}));
  // Without the metric step, or with follow_turn off, the corridor is straight.
  EXPECT_EQ(SelectRoadCorridor(pixels, camera, motion, road.normal, 1.65, 0.0, options),
            std::vector<int>({1}));
  options.follow_turn = false;
  EXPECT_EQ(SelectRoadCorridor(pixels, camera, motion, road.normal, 1.65, 1.0, options),
            std::vector<int>({1}));
}

TEST(RoadCorridor, OptionsRejectNonPositiveSizes) {
  RoadCorridorOptions options;
  EXPECT_NO_THROW(options.Check());
  options.half_width_m = 0.0;
  EXPECT_THROW(options.Check(), Error);
  options = RoadCorridorOptions();
  options.max_distance_m = -1.0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale
