#include "roadscale/scale/road_plane_ransac.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/geometry/angles.h"
#include "roadscale/testing/synthetic_road_scene.h"
#include "roadscale/util/error.h"
#include "roadscale/util/random.h"

namespace roadscale {
namespace {

// A road of pitch 3 degrees and roll 1 degree 1.65 m below the camera, 300 points with 1 %
// height noise, and 200 outliers (40 %): half scattered over car bodies and bushes, half on a
// wall.
struct NoisyRoad {
  Plane road;
  std::vector<Eigen::Vector3d> points;
};

NoisyRoad MakeNoisyRoad(uint32_t seed) {
  NoisyRoad scene;
  scene.road.normal =
      Eigen::Vector3d(-std::sin(1.0 * kRadiansPerDegree), std::cos(3.0 * kRadiansPerDegree),
                      std::sin(3.0 * kRadiansPerDegree))
          .normalized();
  scene.road.height = 1.65;
  Rng rng(seed);
  for (const auto& point : testing::PointsOnPlane(scene.road, 300, -6, 6, 4, 20, seed + 1)) {
    scene.points.push_back(point + 0.01 * 1.65 * rng.Normal() * scene.road.normal);
  }
  for (int i = 0; i < 100; ++i) {
    // One draw a statement: the order of a call's arguments is the compiler's.
    const double depth = rng.Uniform(4.0, 25.0);
    const double height = rng.Uniform(-2.0, 1.5);
    scene.points.emplace_back(rng.Uniform(-8.0, 8.0), height, depth);
  }
  const Plane wall{Eigen::Vector3d::UnitX(), 6.5};
  for (const auto& point : testing::PointsOnPlane(wall, 100, -2.0, 1.6, 5, 25, seed + 2)) {
    scene.points.push_back(point);
  }
  return scene;
}

TEST(RoadPlaneRansac, RecoversHeightWithinHalfAPercentAtFortyPercentOutliers) {
  for (uint32_t seed : {1U, 2U, 3U, 4U, 5U}) {
    const NoisyRoad scene = MakeNoisyRoad(seed);
    const RoadPlaneFit fit =
        FitRoadPlaneRansac(scene.points, Eigen::Vector3d::UnitY(), RoadPlaneRansacOptions());
    ASSERT_EQ(fit.status, RoadPlaneFit::Status::kOk);
    EXPECT_LT(std::abs(fit.plane.height / 1.65 - 1.0), 0.005) << "seed " << seed;
    EXPECT_LT(AngleBetween(fit.plane.normal, scene.road.normal), 0.5 * kRadiansPerDegree)
        << "seed " << seed;
    // The outliers are 40 % of the points; a few of them lie near the road by chance (9 on
    // average, up to 20 in 1,000 seeds), and those only may be inliers: within the inlier
    // band, 5 % of h, of the true road, widened by 2 cm for the fitted plane's own error
    // (1,000 seeds: at most 9.2 cm from the road).
    EXPECT_NEAR(fit.inlier_ratio, 0.6, 0.05) << "seed " << seed;
    for (int index : fit.inliers) {
      if (index < 300) continue;
      EXPECT_LT(std::abs(scene.road.SignedDistance(scene.points[index])), 0.05 * 1.65 + 0.02)
          << "seed " << seed << ", outlier " << index;
    }
  }
}

TEST(RoadPlaneRansac, IsDeterministicForASeed) {
  const NoisyRoad scene = MakeNoisyRoad(9);
  const RoadPlaneRansacOptions options;
  const RoadPlaneFit first = FitRoadPlaneRansac(scene.points, Eigen::Vector3d::UnitY(), options);
  const RoadPlaneFit second = FitRoadPlaneRansac(scene.points, Eigen::Vector3d::UnitY(), options);
  EXPECT_EQ(first.inliers, second.inliers);
  EXPECT_EQ(first.plane.height, second.plane.height);
  EXPECT_EQ(first.iterations, second.iterations);
}

TEST(RoadPlaneRansac, TooFewPointsOrDegenerate) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const RoadPlaneRansacOptions options;
  const auto eleven = testing::PointsOnPlane(road, 11, -3, 3, 5, 15, 1);
  EXPECT_EQ(FitRoadPlaneRansac(eleven, road.normal, options).status,
            RoadPlaneFit::Status::kTooFewPoints);
  const auto twelve = testing::PointsOnPlane(road, 12, -3, 3, 5, 15, 1);
  const RoadPlaneFit fit = FitRoadPlaneRansac(twelve, road.normal, options);
  ASSERT_EQ(fit.status, RoadPlaneFit::Status::kOk);
  EXPECT_NEAR(fit.plane.height, 1.65, 1e-9);
  EXPECT_EQ(fit.inlier_ratio, 1.0);

  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 20; ++i) line.emplace_back(0.1 * i, 1.65, 5.0 + i);
  EXPECT_EQ(FitRoadPlaneRansac(line, road.normal, options).status,
            RoadPlaneFit::Status::kDegenerate);
  // Parallel to the road but above the camera: never a road plane.
  const auto ceiling =
      testing::PointsOnPlane({Eigen::Vector3d::UnitY(), -2.0}, 30, -3, 3, 5, 15, 2);
  EXPECT_EQ(FitRoadPlaneRansac(ceiling, road.normal, options).status,
            RoadPlaneFit::Status::kDegenerate);
}

TEST(RoadPlaneRansac, LeastSquaresPlaneOfKnownPoints) {
  // The corners of a box 4 m wide, 4 m deep and 0.2 m high, 1.5 m to 1.7 m below the camera:
  // the plane of least spread lies halfway between its top and bottom.
  std::vector<Eigen::Vector3d> points;
  for (double x : {-2.0, 2.0}) {
    for (double y : {1.5, 1.7}) {
      for (double z : {5.0, 9.0}) points.emplace_back(x, y, z);
    }
  }
  std::vector<int> all(points.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const std::optional<Plane> plane =
      FitPlaneLeastSquares(points, all, -Eigen::Vector3d::UnitY() + Eigen::Vector3d(0, 0, 0.1));
  ASSERT_TRUE(plane.has_value());
  // Turned away from the given reference (which points up) despite any sign of the solver.
  EXPECT_LT(plane->normal.y(), 0.0);
  EXPECT_NEAR(std::abs(plane->normal.y()), 1.0, 1e-9);
  EXPECT_NEAR(plane->height, -1.6, 1e-9);
  EXPECT_FALSE(FitPlaneLeastSquares(points, {0, 1}, Eigen::Vector3d::UnitY()).has_value());
}

// A pair's road points in a traffic jam (docs/benchmark-history.md, "Traffic jams as a judge"): 12
// near points on the road 1.40 below the camera, and 20 that a plane tilted 11 degrees holds,
// from the near road out to 16 m, as points that moved with the traffic triangulate.
TEST(RoadPlaneRansac, TheTiltLimitKeepsThePlaneTheRoadModelAllows) {
  const Eigen::Vector3d down = Eigen::Vector3d::UnitY();
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 12; ++i) {
    points.emplace_back(-1.5 + 1.0 * (i % 4), 1.40, 7.0 + 0.6 * (i / 4));
  }
  const double slope = std::tan(11.0 * kRadiansPerDegree);
  for (int i = 0; i < 20; ++i) {
    const double z = 7.5 + 0.45 * i;
    points.emplace_back(1.2 - 0.13 * i, 1.40 + slope * (z - 8.0), z);
  }
  RoadPlaneRansacOptions options;
  options.min_points = 6;
  const RoadPlaneFit free = FitRoadPlaneRansac(points, down, options);
  ASSERT_EQ(free.status, RoadPlaneFit::Status::kOk);
  EXPECT_GT(std::acos(free.plane.normal.dot(down)) / kRadiansPerDegree, 6.0);

  options.max_tilt_deg = 5.0;
  const RoadPlaneFit limited = FitRoadPlaneRansac(points, down, options);
  ASSERT_EQ(limited.status, RoadPlaneFit::Status::kOk);
  EXPECT_LT(std::acos(limited.plane.normal.dot(down)) / kRadiansPerDegree, 5.0);
  EXPECT_NEAR(limited.plane.height, 1.40, 0.02);
  for (int index = 0; index < 12; ++index) {
    EXPECT_TRUE(std::binary_search(limited.inliers.begin(), limited.inliers.end(), index));
  }
}

TEST(RoadPlaneRansacOptions, CheckRejectsBadValues) {
  RoadPlaneRansacOptions options;
  EXPECT_NO_THROW(options.Check());
  options.inlier_threshold = 0.0;
  EXPECT_THROW(options.Check(), Error);
  options = RoadPlaneRansacOptions();
  options.min_points = 2;
  EXPECT_THROW(options.Check(), Error);
  options = RoadPlaneRansacOptions();
  options.max_tilt_deg = 90.0;
  EXPECT_THROW(options.Check(), Error);
  options.max_tilt_deg = -1.0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale
