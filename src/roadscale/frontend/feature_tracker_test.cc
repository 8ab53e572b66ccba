#include "roadscale/frontend/feature_tracker.h"

#include <algorithm>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/testing/frontend_test_util.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(FeatureTracker, KeepsIdsAndPixelHistories) {
  FeatureTrackerOptions options;
  options.redetect_below = 0;  // detect on the first frame only
  options.detector.type = DetectorType::kFast;
  options.klt.max_forward_backward_error_px = 0.1;
  FeatureTracker tracker(options);
  const Eigen::Vector2d flow(2.3, 0.8);
  tracker.Track(10, testing::SyntheticTexture(400, 240), cv::Mat());
  ASSERT_GT(tracker.Detect(cv::Mat(), /*force=*/true), 50);
  std::map<int64_t, Eigen::Vector2d> start;
  for (const Track& track : tracker.tracks()) start[track.id] = track.pixels.front();

  for (int k = 1; k <= 4; ++k) {
    tracker.Track(10 + k, testing::SyntheticTexture(400, 240, k * flow.x(), k * flow.y()),
                  cv::Mat());
    EXPECT_EQ(tracker.Detect(cv::Mat()), 0);
  }
  EXPECT_EQ(tracker.current_frame(), 14);
  ASSERT_GT(tracker.tracks().size(), 0.8 * start.size());
  std::vector<double> step_errors;
  for (const Track& track : tracker.tracks()) {
    ASSERT_TRUE(start.count(track.id));
    EXPECT_EQ(track.first_frame, 10);
    ASSERT_EQ(track.length(), 5);
    EXPECT_EQ(track.last_frame(), 14);
    EXPECT_EQ(track.pixels.front(), start[track.id]);
    for (int k = 1; k < 5; ++k) {
      const double error = (track.pixels[k] - track.pixels[k - 1] - flow).norm();
      EXPECT_LT(error, 0.15) << "track " << track.id << " step " << k;
      step_errors.push_back(error);
    }
  }
  std::nth_element(step_errors.begin(), step_errors.begin() + step_errors.size() / 2,
                   step_errors.end());
  EXPECT_LT(step_errors[step_errors.size() / 2], 0.02);
}

TEST(FeatureTracker, RedetectsWhenTracksRunLow) {
  FeatureTrackerOptions options;
  options.redetect_below = 10000;  // always below: top up every frame
  FeatureTracker tracker(options);
  tracker.Track(0, testing::SyntheticTexture(300, 200), cv::Mat());
  const int first = tracker.Detect(cv::Mat());
  ASSERT_GT(first, 20);
  // A 40 px shift moves a fifth of the tracks out of the image; re-detection fills in.
  tracker.Track(1, testing::SyntheticTexture(300, 200, 40.0, 0.0), cv::Mat());
  const int tracked = static_cast<int>(tracker.tracks().size());
  EXPECT_LT(tracked, first);
  EXPECT_GT(tracker.Detect(cv::Mat()), 0);
  EXPECT_EQ(tracker.stats().tracked, tracked);
  int64_t max_old_id = -1;
  for (const Track& track : tracker.tracks()) {
    if (track.first_frame == 0) max_old_id = std::max(max_old_id, track.id);
  }
  for (const Track& track : tracker.tracks()) {
    if (track.first_frame == 1) {
      EXPECT_GT(track.id, max_old_id);
      EXPECT_EQ(track.length(), 1);
    }
  }
}

TEST(FeatureTracker, DropsTracksOnTheDynamicMaskAndOnRequest) {
  FeatureTracker tracker({});
  tracker.Track(0, testing::SyntheticTexture(300, 200), cv::Mat());
  tracker.Detect(cv::Mat(), true);
  cv::Mat dynamic(200, 300, CV_8UC1, cv::Scalar(0));
  dynamic(cv::Rect(0, 0, 150, 200)).setTo(255);
  tracker.Track(1, testing::SyntheticTexture(300, 200, 1.0, 0.0), dynamic);
  ASSERT_FALSE(tracker.tracks().empty());
  EXPECT_GT(tracker.stats().dropped_dynamic, 0);
  for (const Track& track : tracker.tracks()) EXPECT_GE(track.pixels.back().x(), 149.5);

  const int64_t victim = tracker.tracks().front().id;
  const size_t before = tracker.tracks().size();
  tracker.Drop({victim});
  EXPECT_EQ(tracker.tracks().size(), before - 1);
  for (const Track& track : tracker.tracks()) EXPECT_NE(track.id, victim);
}

TEST(FeatureTracker, DropsTracksByTheirPixelInAnEarlierSegmentedFrame) {
  FeatureTracker tracker({});
  tracker.Track(0, testing::SyntheticTexture(300, 200), cv::Mat());
  tracker.Detect(cv::Mat(), true);
  // The texture moves 30 px to the right in three frames: a track left of x = 100 in frame 0
  // is right of it by frame 3, where only its frame-0 pixel shows it was on the mask.
  for (int k = 1; k <= 3; ++k) {
    tracker.Track(k, testing::SyntheticTexture(300, 200, 10.0 * k, 0.0), cv::Mat());
  }
  tracker.Detect(cv::Mat(), true);  // tracks born in frame 3 have no frame-0 pixel
  cv::Mat frame0_dynamic(200, 300, CV_8UC1, cv::Scalar(0));
  frame0_dynamic(cv::Rect(0, 0, 100, 200)).setTo(255);
  int on_mask_in_frame0 = 0;
  for (const Track& track : tracker.tracks()) {
    if (track.first_frame == 0 && track.pixels.front().x() < 99.5) ++on_mask_in_frame0;
  }
  ASSERT_GT(on_mask_in_frame0, 0);
  const size_t before = tracker.tracks().size();

  const std::vector<int64_t> dropped = tracker.DropOnMaskAt(0, frame0_dynamic);
  EXPECT_EQ(static_cast<int>(dropped.size()), on_mask_in_frame0);
  EXPECT_EQ(tracker.tracks().size(), before - dropped.size());
  EXPECT_EQ(tracker.stats().dropped_dynamic, static_cast<int>(dropped.size()));
  bool kept_one_born_later_on_the_mask_area = false;
  for (const Track& track : tracker.tracks()) {
    if (track.first_frame == 0) {
      EXPECT_GE(track.pixels.front().x(), 99.5);
    }
    if (track.first_frame == 3 && track.pixels.back().x() < 99.5) {
      kept_one_born_later_on_the_mask_area = true;
    }
  }
  EXPECT_TRUE(kept_one_born_later_on_the_mask_area);
  EXPECT_THROW(tracker.DropOnMaskAt(0, cv::Mat(10, 10, CV_8UC1)), Error);
}

TEST(FeatureTracker, RejectsFramesOutOfOrderAndBadImages) {
  FeatureTracker tracker({});
  EXPECT_THROW(tracker.Detect(cv::Mat()), Error);
  tracker.Track(0, testing::SyntheticTexture(100, 80), cv::Mat());
  EXPECT_THROW(tracker.Track(2, testing::SyntheticTexture(100, 80), cv::Mat()), Error);
  EXPECT_THROW(tracker.Track(1, testing::SyntheticTexture(90, 80), cv::Mat()), Error);
  EXPECT_THROW(tracker.Track(1, cv::Mat(80, 100, CV_8UC3), cv::Mat()), Error);
  EXPECT_THROW(tracker.Track(1, testing::SyntheticTexture(100, 80), cv::Mat(80, 100, CV_32F)),
               Error);
}

}  // namespace
}  // namespace roadscale
