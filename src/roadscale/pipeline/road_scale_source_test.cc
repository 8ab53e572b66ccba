#include "roadscale/pipeline/road_scale_source.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/testing/synthetic_road_scene.h"

namespace roadscale {
namespace {

// A frontend result for a synthetic street seen from two cameras 1.1 m apart: every track an
// inlier except a few mismatches with ids the motion left out.
FrontendFrame StreetFrame(MotionStatus status) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  testing::SceneOptions scene;
  scene.num_road = 800;
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.1, 0.01);
  const testing::TwoViewObservations pair = testing::ObserveTwoViews(
      testing::MakeStreetScene(scene), motion, KittiOdometryCamera(), 0.3, 5);
  FrontendFrame frame;
  frame.motion.status = status;
  frame.motion.rotation = motion.linear();
  frame.motion.direction = motion.translation().normalized();
  for (size_t i = 0; i < pair.prev_pixels.size(); ++i) {
    frame.correspondences.push_back(
        {static_cast<int64_t>(i), pair.prev_pixels[i], pair.cur_pixels[i]});
    frame.motion.inlier_track_ids.push_back(static_cast<int64_t>(i));
  }
  for (int k = 0; k < 20; ++k) {
    frame.correspondences.push_back(
        {100000 + k, Eigen::Vector2d(600 + 10 * k, 300), Eigen::Vector2d(100 + 10 * k, 200)});
  }
  return frame;
}

ScaleQuery QueryOf(const FrontendFrame& frame, size_t position) {
  ScaleQuery query;
  query.position = position;
  query.frontend = &frame;
  return query;
}

TEST(RoadScaleSource, ScalesTheFrontendsMotionFromTheRoad) {
  RoadScaleSource source(KittiOdometryCamera(), ScaleEstimatorOptions());
  EXPECT_EQ(source.Name(), "road");
  const FrontendFrame frame = StreetFrame(MotionStatus::kOk);
  const ScaleResult result = source.StepLength(QueryOf(frame, 1));
  ASSERT_TRUE(result.valid);
  EXPECT_TRUE(result.measured);
  EXPECT_EQ(result.status, "ok");
  EXPECT_LT(std::abs(result.step_length_m / 1.1 - 1.0), 0.01);
  // Only the motion's inliers reach the estimator.
  EXPECT_EQ(source.last_estimate().num_tracks, static_cast<int>(frame.correspondences.size()) - 20);
  // One value per diagnostics column.
  const std::string header = source.DiagnosticsCsvHeader();
  EXPECT_EQ(std::count(result.diagnostics_csv.begin(), result.diagnostics_csv.end(), ','),
            std::count(header.begin(), header.end(), ','));
}

TEST(RoadScaleSource, APairWithoutRoadPointsHoldsTheLastLengthAsNotMeasured) {
  RoadScaleSource source(KittiOdometryCamera(), ScaleEstimatorOptions());
  const FrontendFrame street = StreetFrame(MotionStatus::kOk);
  const ScaleResult fitted = source.StepLength(QueryOf(street, 1));
  ASSERT_TRUE(fitted.measured);

  FrontendFrame no_road = street;
  no_road.correspondences.resize(3);
  const ScaleResult held = source.StepLength(QueryOf(no_road, 2));
  EXPECT_TRUE(held.valid);
  EXPECT_FALSE(held.measured);
  EXPECT_EQ(held.status, "held: too few points");
  EXPECT_DOUBLE_EQ(held.step_length_m, fitted.step_length_m);
}

TEST(RoadScaleSource, FramesWithoutMotionHaveNoLength) {
  RoadScaleSource source(KittiOdometryCamera(), ScaleEstimatorOptions());
  const FrontendFrame frame = StreetFrame(MotionStatus::kPureRotation);
  const ScaleResult result = source.StepLength(QueryOf(frame, 1));
  EXPECT_FALSE(result.valid);
  EXPECT_FALSE(result.measured);
  EXPECT_EQ(result.status.rfind("no motion: ", 0), 0U) << result.status;
  EXPECT_TRUE(result.diagnostics_csv.empty());
}

}  // namespace
}  // namespace roadscale
