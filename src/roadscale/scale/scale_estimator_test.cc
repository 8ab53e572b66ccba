#include "roadscale/scale/scale_estimator.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/geometry/angles.h"
#include "roadscale/testing/synthetic_road_scene.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

constexpr double kStep = 1.2;  // metres between the two cameras

ScaleEstimatorOptions Unfiltered() {
  ScaleEstimatorOptions options;
  options.use_filter = false;
  return options;
}

testing::TwoViewObservations StreetPair(const Plane& road, uint32_t seed, double yaw_rad) {
  testing::SceneOptions scene;
  scene.road = road;
  scene.num_road = 800;
  scene.seed = seed;
  return testing::ObserveTwoViews(testing::MakeStreetScene(scene),
                                  testing::DriveAlongRoad(road, kStep, yaw_rad),
                                  KittiOdometryCamera(), 0.3, seed + 100);
}

TEST(ScaleEstimator, StreetWithWallsAndACarGivesScaleWithinOnePercent) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  for (uint32_t seed : {1U, 2U, 3U, 4U, 5U}) {
    const testing::TwoViewObservations pair = StreetPair(road, seed, 0.03);
    ScaleEstimator estimator(KittiOdometryCamera(), Unfiltered());
    const ScaleEstimate estimate = estimator.Estimate(
        pair.prev_pixels, pair.cur_pixels, testing::DriveAlongRoad(road, kStep, 0.03), cv::Mat());
    ASSERT_EQ(estimate.status, ScaleStatus::kOk) << "seed " << seed;
    EXPECT_TRUE(estimate.has_scale);
    EXPECT_LT(std::abs(estimate.raw_scale / kStep - 1.0), 0.01) << "seed " << seed;
    EXPECT_EQ(estimate.scale, estimate.raw_scale);
    EXPECT_LT(AngleBetween(estimate.plane.normal, road.normal), 1.0 * kRadiansPerDegree);
    EXPECT_NEAR(estimate.plane.height * estimate.raw_scale, 1.65, 1e-9);
    // Counts shrink stage by stage, and the plane's inliers are road points.
    EXPECT_EQ(estimate.num_tracks, static_cast<int>(pair.prev_pixels.size()));
    EXPECT_LE(estimate.num_triangulated, estimate.num_tracks);
    EXPECT_LE(estimate.num_preselected, estimate.num_triangulated);
    EXPECT_LE(estimate.num_after_vote, estimate.num_preselected);
    EXPECT_LE(estimate.num_after_road_model, estimate.num_after_vote);
    EXPECT_EQ(estimate.num_ransac_inliers, static_cast<int>(estimate.road_track_indices.size()));
    EXPECT_GE(estimate.num_ransac_inliers, 12);
    EXPECT_NEAR(estimate.inlier_ratio,
                static_cast<double>(estimate.num_ransac_inliers) / estimate.num_after_road_model,
                1e-12);
    // Wall and car points near the road are road as far as geometry can tell: RANSAC keeps
    // the triangulated points within 5 % of h (8 cm), and 0.3 px of noise moves a point 10-30 m
    // ahead by centimetres more. Nothing higher may be an inlier (200 seeds: the highest true
    // height of an inlier at most 0.18 m, above 0.12 m in one of 20; the car's roof is at 1.5 m).
    for (int track : estimate.road_track_indices) {
      EXPECT_LT(std::abs(road.SignedDistance(pair.points[track])), 0.25) << "seed " << seed;
    }
    EXPECT_FALSE(estimate.used_road_mask);
  }
}

TEST(ScaleEstimator, RoadOfKnownPitchWithARoadMask) {
  for (double pitch_deg : {-5.0, 5.0}) {
    const Plane road{Eigen::Vector3d(0, std::cos(pitch_deg * kRadiansPerDegree),
                                     std::sin(pitch_deg * kRadiansPerDegree)),
                     1.65};
    const testing::TwoViewObservations pair = StreetPair(road, 7, -0.02);
    // The segmentation also calls the car's pixels road: the geometry must reject them.
    const cv::Mat mask = testing::MaskFromLabels(
        pair, KittiOdometryCamera(), {testing::SceneLabel::kRoad, testing::SceneLabel::kCar}, 4);
    ScaleEstimator estimator(KittiOdometryCamera(), Unfiltered());
    const ScaleEstimate estimate = estimator.Estimate(
        pair.prev_pixels, pair.cur_pixels, testing::DriveAlongRoad(road, kStep, -0.02), mask);
    ASSERT_EQ(estimate.status, ScaleStatus::kOk);
    EXPECT_TRUE(estimate.used_road_mask);
    EXPECT_LT(std::abs(estimate.raw_scale / kStep - 1.0), 0.01) << pitch_deg;
    EXPECT_NEAR(estimate.plane.PitchRad(), pitch_deg * kRadiansPerDegree, 1.0 * kRadiansPerDegree);
    for (int track : estimate.road_track_indices) {
      EXPECT_LT(std::abs(road.SignedDistance(pair.points[track])), 0.1) << pitch_deg;
    }
  }
}

TEST(ScaleEstimator, StagesCanBeSwitchedOff) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const testing::TwoViewObservations pair = StreetPair(road, 3, 0.0);
  const Rigid3d motion = testing::DriveAlongRoad(road, kStep, 0.0);
  ScaleEstimatorOptions options = Unfiltered();
  options.use_horizon = false;
  options.use_depth_vote = false;
  options.use_road_model_check = false;
  ScaleEstimator estimator(KittiOdometryCamera(), options);
  const ScaleEstimate estimate =
      estimator.Estimate(pair.prev_pixels, pair.cur_pixels, motion, cv::Mat());
  EXPECT_EQ(estimate.num_preselected, estimate.num_triangulated);
  EXPECT_EQ(estimate.num_after_vote, estimate.num_triangulated);
  EXPECT_EQ(estimate.num_after_road_model, estimate.num_triangulated);
  // Segmentation off: a mask is ignored.
  options = Unfiltered();
  options.use_segmentation = false;
  ScaleEstimator without_mask(KittiOdometryCamera(), options);
  const cv::Mat nothing_is_road(376, 1241, CV_8UC1, cv::Scalar(0));
  const ScaleEstimate ignored =
      without_mask.Estimate(pair.prev_pixels, pair.cur_pixels, motion, nothing_is_road);
  EXPECT_FALSE(ignored.used_road_mask);
  EXPECT_EQ(ignored.status, ScaleStatus::kOk);
}

TEST(ScaleEstimator, HoldsThePreviousModelAndSaysWhy) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const testing::TwoViewObservations pair = StreetPair(road, 4, 0.0);
  const Rigid3d motion = testing::DriveAlongRoad(road, kStep, 0.0);
  ScaleEstimator estimator(KittiOdometryCamera(), ScaleEstimatorOptions());
  const std::vector<Eigen::Vector2d> few_prev(pair.prev_pixels.begin(),
                                              pair.prev_pixels.begin() + 5);
  const std::vector<Eigen::Vector2d> few_cur(pair.cur_pixels.begin(), pair.cur_pixels.begin() + 5);

  // Nothing to hold yet.
  ScaleEstimate estimate = estimator.Estimate(few_prev, few_cur, motion, cv::Mat());
  EXPECT_EQ(estimate.status, ScaleStatus::kHeldTooFewPoints);
  EXPECT_STREQ(ScaleStatusName(estimate.status), "held: too few points");
  EXPECT_FALSE(estimate.has_scale);
  EXPECT_TRUE(std::isnan(estimate.raw_scale));
  EXPECT_TRUE(std::isnan(estimate.scale));

  const ScaleEstimate fitted =
      estimator.Estimate(pair.prev_pixels, pair.cur_pixels, motion, cv::Mat());
  ASSERT_EQ(fitted.status, ScaleStatus::kOk);
  EXPECT_EQ(fitted.scale, fitted.raw_scale);  // one value in the window

  estimate = estimator.Estimate(few_prev, few_cur, motion, cv::Mat());
  EXPECT_EQ(estimate.status, ScaleStatus::kHeldTooFewPoints);
  EXPECT_TRUE(estimate.has_scale);
  EXPECT_EQ(estimate.raw_scale, fitted.raw_scale);
  EXPECT_EQ(estimate.plane.height, fitted.plane.height);
  // The held scale entered the window: [s, s].
  EXPECT_NEAR(estimate.scale, fitted.raw_scale, 1e-12);

  estimate = estimator.Estimate(pair.prev_pixels, pair.cur_pixels, Rigid3d::Identity(), cv::Mat());
  EXPECT_EQ(estimate.status, ScaleStatus::kNoMotion);
  EXPECT_STREQ(ScaleStatusName(estimate.status), "no motion");
  EXPECT_EQ(estimate.raw_scale, fitted.raw_scale);

  estimator.Reset();
  estimate = estimator.Estimate(few_prev, few_cur, motion, cv::Mat());
  EXPECT_FALSE(estimate.has_scale);
}

TEST(ScaleEstimator, FilterSmoothsOverFrames) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  ScaleEstimator estimator(KittiOdometryCamera(), ScaleEstimatorOptions());
  double sum_abs_raw = 0.0;
  ScaleEstimate last;
  for (uint32_t frame = 0; frame < 8; ++frame) {
    const testing::TwoViewObservations pair = StreetPair(road, 20 + frame, 0.0);
    last = estimator.Estimate(pair.prev_pixels, pair.cur_pixels,
                              testing::DriveAlongRoad(road, kStep, 0.0), cv::Mat());
    ASSERT_EQ(last.status, ScaleStatus::kOk);
    sum_abs_raw += std::abs(last.raw_scale / kStep - 1.0);
  }
  EXPECT_LT(std::abs(last.scale / kStep - 1.0), 0.01);
  EXPECT_LT(sum_abs_raw / 8.0, 0.01);
}

TEST(ScaleEstimator, RejectsBadInput) {
  ScaleEstimatorOptions options;
  options.camera_height = 0.0;
  EXPECT_THROW(ScaleEstimator(KittiOdometryCamera(), options), Error);
  options = ScaleEstimatorOptions();
  options.road_model.max_angle_deg = -1.0;
  EXPECT_THROW(ScaleEstimator(KittiOdometryCamera(), options), Error);
  ScaleEstimator estimator(KittiOdometryCamera(), ScaleEstimatorOptions());
  const Rigid3d motion = MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -1));
  EXPECT_THROW(estimator.Estimate({{1, 2}}, {}, motion, cv::Mat()), Error);
  const cv::Mat colour(376, 1241, CV_8UC3);
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const testing::TwoViewObservations pair = StreetPair(road, 4, 0.0);
  EXPECT_THROW(estimator.Estimate(pair.prev_pixels, pair.cur_pixels, motion, colour), Error);
}

}  // namespace
}  // namespace roadscale
