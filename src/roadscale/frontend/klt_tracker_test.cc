#include "roadscale/frontend/klt_tracker.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/testing/frontend_test_util.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::vector<cv::Point2f> GridPoints(int width, int height, int step, int margin) {
  std::vector<cv::Point2f> points;
  for (int y = margin; y < height - margin; y += step) {
    for (int x = margin; x < width - margin; x += step) {
      points.emplace_back(static_cast<float>(x) + 0.25f, static_cast<float>(y) + 0.6f);
    }
  }
  return points;
}

TEST(KltTracker, FollowsASubPixelShift) {
  const double dx = 3.37;
  const double dy = -1.71;
  const cv::Mat prev = testing::SyntheticTexture(320, 240);
  const cv::Mat cur = testing::SyntheticTexture(320, 240, dx, dy);
  const KltOptions options;
  const std::vector<cv::Point2f> points = GridPoints(320, 240, 20, 30);
  const KltResult result =
      TrackKlt(BuildKltPyramid(prev, options), BuildKltPyramid(cur, options), points, {}, options);
  ASSERT_EQ(result.points.size(), points.size());
  int ok = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!result.ok[i]) continue;
    ++ok;
    EXPECT_NEAR(result.points[i].x - points[i].x, dx, 0.05) << i;
    EXPECT_NEAR(result.points[i].y - points[i].y, dy, 0.05) << i;
    EXPECT_LT(result.forward_backward_error[i], 0.1f);
  }
  EXPECT_GE(ok, static_cast<int>(0.95 * points.size()));
}

TEST(KltTracker, FollowsALargeShiftThroughThePyramid) {
  const double dx = -37.6;
  const double dy = 12.2;
  const cv::Mat prev = testing::SyntheticTexture(400, 300);
  const cv::Mat cur = testing::SyntheticTexture(400, 300, dx, dy);
  const KltOptions options;
  const std::vector<cv::Point2f> points = GridPoints(400, 300, 25, 60);
  const KltResult result =
      TrackKlt(BuildKltPyramid(prev, options), BuildKltPyramid(cur, options), points, {}, options);
  int ok = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!result.ok[i]) continue;
    ++ok;
    EXPECT_NEAR(result.points[i].x - points[i].x, dx, 0.05) << i;
    EXPECT_NEAR(result.points[i].y - points[i].y, dy, 0.05) << i;
  }
  EXPECT_GE(ok, static_cast<int>(0.8 * points.size()));
}

TEST(KltTracker, UsesThePredictedPosition) {
  // 150 px is beyond what a 3-level pyramid finds alone; a prediction 2 px off is enough.
  const double dx = 150.4;
  const cv::Mat prev = testing::SyntheticTexture(500, 200);
  const cv::Mat cur = testing::SyntheticTexture(500, 200, dx, 0.0);
  const KltOptions options;
  std::vector<cv::Point2f> points;
  std::vector<cv::Point2f> predicted;
  for (int x = 40; x < 300; x += 20) {
    points.emplace_back(static_cast<float>(x), 100.0f);
    predicted.emplace_back(static_cast<float>(x + dx - 2.0), 101.5f);
  }
  const KltResult result = TrackKlt(BuildKltPyramid(prev, options), BuildKltPyramid(cur, options),
                                    points, predicted, options);
  for (size_t i = 0; i < points.size(); ++i) {
    ASSERT_TRUE(result.ok[i]) << i;
    EXPECT_NEAR(result.points[i].x - points[i].x, dx, 0.05);
    EXPECT_NEAR(result.points[i].y - points[i].y, 0.0, 0.05);
  }
}

TEST(KltTracker, RejectsOccludedAndOutsidePoints) {
  const double dx = 6.0;
  const cv::Mat prev = testing::SyntheticTexture(320, 240);
  cv::Mat cur = testing::SyntheticTexture(320, 240, dx, 0.0);
  // An "object" of different texture covers the middle of the current frame.
  testing::SyntheticTexture(320, 240, 0.0, 0.0, 99)(cv::Rect(120, 80, 80, 80))
      .copyTo(cur(cv::Rect(120, 80, 80, 80)));
  const KltOptions options;
  const std::vector<cv::Point2f> points = {{160.0f, 120.0f}, {60.0f, 60.0f}, {316.0f, 120.0f}};
  const KltResult result =
      TrackKlt(BuildKltPyramid(prev, options), BuildKltPyramid(cur, options), points, {}, options);
  EXPECT_FALSE(result.ok[0]) << "inside the occluder";
  EXPECT_TRUE(result.ok[1]);
  EXPECT_FALSE(result.ok[2]) << "moved out of the image";
}

TEST(KltTracker, BackwardPassFromEitherLevelFollowsLargeShiftsAndRejectsOccluders) {
  // The forward pass needs the pyramid for a 37 px shift; the backward pass starts at the
  // point's start and comes back from the finest level alone as well as through the pyramid.
  const double dx = -37.6;
  const double dy = 12.2;
  const cv::Mat prev = testing::SyntheticTexture(400, 300);
  cv::Mat cur = testing::SyntheticTexture(400, 300, dx, dy);
  const cv::Rect occluder(160, 110, 80, 80);
  testing::SyntheticTexture(400, 300, 0.0, 0.0, 99)(occluder).copyTo(cur(occluder));
  std::vector<cv::Point2f> points = GridPoints(400, 300, 25, 60);
  const cv::Point2f occluded(200.0f - static_cast<float>(dx), 150.0f - static_cast<float>(dy));
  points.push_back(occluded);
  for (const int levels : {0, 3}) {
    KltOptions options;
    options.backward_pyramid_levels = levels;
    const KltResult result = TrackKlt(BuildKltPyramid(prev, options), BuildKltPyramid(cur, options),
                                      points, {}, options);
    int ok = 0;
    int wrong = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
      if (!result.ok[i]) continue;
      ++ok;
      const cv::Point2f truth = points[i] + cv::Point2f(dx, dy);
      const cv::Point2f error = result.points[i] - truth;
      // A window that takes in some of the occluder's pixels is pulled by them by a fraction
      // of a pixel (0.46 px once here), and the way back, pulled alike, cannot see it.
      const int half = options.window_size / 2;
      const cv::Rect window(cvRound(truth.x) - half, cvRound(truth.y) - half, options.window_size,
                            options.window_size);
      const double tolerance =
          (window & occluder).empty() ? 0.05 : options.max_forward_backward_error_px;
      if (std::abs(error.x) > tolerance || std::abs(error.y) > tolerance) ++wrong;
    }
    EXPECT_GE(ok, static_cast<int>(0.7 * points.size())) << "levels " << levels;
    EXPECT_FALSE(result.ok.back()) << "inside the occluder, levels " << levels;
    // The weakness of the finest level alone: a track that KLT sent far off can stall at its
    // start on the way back and pass, which is why the default returns through the whole
    // pyramid (docs/benchmark-history.md, "CPU without the network"). None passes wrong on this
    // texture; on 200 textures of its kind 40 tracks clear of the occluder did, 20 when
    // returning through the pyramid.
    EXPECT_LE(wrong, levels == 0 ? 1 : 0) << "levels " << levels;
  }
}

TEST(KltTracker, RejectsBadInput) {
  const KltOptions options;
  EXPECT_THROW(BuildKltPyramid(cv::Mat(), options), Error);
  EXPECT_THROW(BuildKltPyramid(cv::Mat(10, 10, CV_8UC3), options), Error);
  KltOptions bad;
  bad.window_size = 20;
  EXPECT_THROW(bad.Check(), Error);
  bad = KltOptions();
  bad.max_forward_backward_error_px = 0.0;
  EXPECT_THROW(bad.Check(), Error);
  bad = KltOptions();
  bad.backward_pyramid_levels = -1;
  EXPECT_THROW(bad.Check(), Error);
  const KltPyramid a = BuildKltPyramid(testing::SyntheticTexture(100, 80), options);
  const KltPyramid b = BuildKltPyramid(testing::SyntheticTexture(90, 80), options);
  EXPECT_THROW(TrackKlt(a, b, {{50.0f, 40.0f}}, {}, options), Error);
}

}  // namespace
}  // namespace roadscale
