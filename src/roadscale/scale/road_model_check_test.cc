#include "roadscale/scale/road_model_check.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/geometry/angles.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/scale/road_plane.h"
#include "roadscale/testing/synthetic_road_scene.h"

namespace roadscale {
namespace {

Plane PlaneOfPitch(double pitch_deg) {
  return {Eigen::Vector3d(0.0, std::cos(pitch_deg * kRadiansPerDegree),
                          std::sin(pitch_deg * kRadiansPerDegree)),
          1.65};
}

std::vector<Eigen::Vector2d> ProjectAll(const std::vector<Eigen::Vector3d>& points) {
  const PinholeCamera camera = KittiOdometryCamera();
  std::vector<Eigen::Vector2d> pixels;
  for (const auto& point : points) pixels.push_back(camera.Project(point));
  return pixels;
}

TEST(RoadModelCheck, RemovesVerticalAndTiltedTriangles) {
  const Plane road = PlaneOfPitch(0.0);
  std::vector<Eigen::Vector3d> points = testing::PointsOnPlane(road, 300, -6, 6, 5, 25, 11);
  const size_t num_road = points.size();
  // A wall 7 m to the right (normal along x) from 0.45 m above the road up to camera level,
  // and a ramp of 25 degrees standing on the road
  // to the left (a car's windscreen, a slope beside the road).
  const Plane wall{Eigen::Vector3d::UnitX(), 7.0};
  for (const auto& point : testing::PointsOnPlane(wall, 60, 0.0, 1.2, 8, 25, 12)) {
    points.push_back(point);
  }
  Plane ramp = PlaneOfPitch(25.0);
  ramp.height = 5.1;  // from the road (y = 1.45 m) up to camera level, 9 to 12 m ahead
  for (const auto& point : testing::PointsOnPlane(ramp, 60, -9, -7, 7.5, 11, 13)) {
    points.push_back(point);
  }
  const RoadModelCheck check =
      CheckRoadModel(ProjectAll(points), points, road.normal, RoadModelCheckOptions());
  EXPECT_GT(check.num_triangles, 0);
  int road_kept = 0;
  int others_kept = 0;
  for (int index : check.kept) (static_cast<size_t>(index) < num_road ? road_kept : others_kept)++;
  // Road points only lose triangles they share with the wall or the ramp. An image triangle
  // can join a wall point to road points 10 m away from it, and such a long, flat triangle
  // passes: the check cannot remove every wall point, RANSAC sees the few left.
  EXPECT_GE(road_kept, 0.9 * static_cast<double>(num_road));
  EXPECT_LE(others_kept, 6);
  // Triangles of wall points only or of ramp points only never pass.
  const std::vector<Eigen::Vector3d> wall_only(points.begin() + num_road,
                                               points.begin() + num_road + 60);
  EXPECT_TRUE(CheckRoadModel(ProjectAll(wall_only), wall_only, road.normal, RoadModelCheckOptions())
                  .kept.empty());
  const std::vector<Eigen::Vector3d> ramp_only(points.begin() + num_road + 60, points.end());
  EXPECT_TRUE(CheckRoadModel(ProjectAll(ramp_only), ramp_only, road.normal, RoadModelCheckOptions())
                  .kept.empty());
}

TEST(RoadModelCheck, RoadOfKnownPitchAgainstMotionOfKnownGrade) {
  for (double pitch_deg : {-5.0, 5.0}) {
    const Plane road = PlaneOfPitch(pitch_deg);
    const std::vector<Eigen::Vector3d> points = testing::PointsOnPlane(road, 200, -6, 6, 5, 25, 21);
    const std::vector<Eigen::Vector2d> pixels = ProjectAll(points);
    const RoadModelCheckOptions options;
    // Driving along the road: its normal is the expected one, every point is kept.
    const std::optional<Eigen::Vector3d> along =
        ExpectedRoadNormal(testing::DriveAlongRoad(road, 1.0, 0.02), options);
    ASSERT_TRUE(along.has_value());
    EXPECT_NEAR(AngleBetween(*along, road.normal), 0.0, 1e-9);
    EXPECT_EQ(CheckRoadModel(pixels, points, *along, options).kept.size(), points.size());
    // Driving along the opposite grade: the expected normal is 10 degrees off, nothing kept.
    const Plane opposite = PlaneOfPitch(-pitch_deg);
    const std::optional<Eigen::Vector3d> crossing =
        ExpectedRoadNormal(testing::DriveAlongRoad(opposite, 1.0, 0.0), options);
    ASSERT_TRUE(crossing.has_value());
    EXPECT_NEAR(AngleBetween(*crossing, road.normal), 10.0 * kRadiansPerDegree, 1e-9);
    EXPECT_TRUE(CheckRoadModel(pixels, points, *crossing, options).kept.empty());
  }
}

TEST(RoadModelCheck, ThresholdIsTheAngleToTheExpectedNormal) {
  const Eigen::Vector3d expected = Eigen::Vector3d::UnitY();
  RoadModelCheckOptions options;
  for (double pitch_deg : {4.9, -4.9, 5.1, -5.1}) {
    const Plane road = PlaneOfPitch(pitch_deg);
    const auto points = testing::PointsOnPlane(road, 50, -6, 6, 5, 25, 31);
    const size_t kept = CheckRoadModel(ProjectAll(points), points, expected, options).kept.size();
    EXPECT_EQ(kept, std::abs(pitch_deg) < 5.0 ? points.size() : 0U) << pitch_deg;
  }
  // The same holds across the road (roll), where a pitch-only test would see nothing.
  Plane rolled{
      Eigen::Vector3d(std::sin(6.0 * kRadiansPerDegree), std::cos(6.0 * kRadiansPerDegree), 0.0),
      1.65};
  const auto points = testing::PointsOnPlane(rolled, 50, -6, 6, 5, 25, 32);
  EXPECT_TRUE(CheckRoadModel(ProjectAll(points), points, expected, options).kept.empty());
  options.max_angle_deg = 7.0;
  EXPECT_EQ(CheckRoadModel(ProjectAll(points), points, expected, options).kept.size(),
            points.size());
}

TEST(RoadModelCheck, FixedPitchIgnoresTheMotion) {
  RoadModelCheckOptions options;
  options.reference = RoadModelCheckOptions::Reference::kFixedPitch;
  options.camera_pitch_deg = 2.0;
  const Rigid3d uphill = testing::DriveAlongRoad(PlaneOfPitch(8.0), 1.0, 0.0);
  const std::optional<Eigen::Vector3d> normal = ExpectedRoadNormal(uphill, options);
  ASSERT_TRUE(normal.has_value());
  EXPECT_TRUE(normal->isApprox(PlaneOfPitch(2.0).normal, 1e-12));
  EXPECT_TRUE(ExpectedRoadNormal(Rigid3d::Identity(), options).has_value());
  options.reference = RoadModelCheckOptions::Reference::kMotion;
  EXPECT_FALSE(ExpectedRoadNormal(Rigid3d::Identity(), options).has_value());
  const std::optional<Eigen::Vector3d> from_motion = ExpectedRoadNormal(uphill, options);
  ASSERT_TRUE(from_motion.has_value());
  EXPECT_TRUE(from_motion->isApprox(PlaneOfPitch(8.0).normal, 1e-12));
}

TEST(RoadModelCheck, TrianglesAboveTheCameraAreNotRoad) {
  // A ceiling parallel to the road: right normal, but the camera is below it (h < 0).
  const Plane ceiling{Eigen::Vector3d::UnitY(), -3.0};
  const auto points = testing::PointsOnPlane(ceiling, 50, -6, 6, 5, 25, 41);
  EXPECT_TRUE(
      CheckRoadModel(ProjectAll(points), points, Eigen::Vector3d::UnitY(), RoadModelCheckOptions())
          .kept.empty());
}

}  // namespace
}  // namespace roadscale
