#include "roadscale/pipeline/sequential_pipeline.h"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

namespace roadscale {
namespace {

TEST(SequentialPipeline, FrameRecordCsvHasOneFieldPerHeaderColumn) {
  FrameRecord record;
  record.scale_status = "oracle";
  const auto count = [](const std::string& text) {
    return std::count(text.begin(), text.end(), ',');
  };
  EXPECT_EQ(count(FrameRecordCsvHeader()), count(FormatFrameRecordCsv(record)));
}

TEST(SequentialPipeline, RecordsTheRoadPixelsAndTheTracksOnTheRoad) {
  TrackedFrame tracked;
  // Road: the bottom half of a 20 x 10 image.
  cv::Mat road(10, 20, CV_8UC1, cv::Scalar(0));
  road.rowRange(5, 10).setTo(255);
  tracked.frontend.observations = {{1, {3.0, 7.2}},    // on the road
                                   {2, {15.0, 4.6}},   // rounds to row 5: on the road
                                   {3, {8.0, 2.0}},    // above it
                                   {4, {25.0, 8.0}}};  // outside the image
  SetRoadMask(road, &tracked);
  EXPECT_EQ(tracked.record.road_mask_px, 100);
  EXPECT_EQ(tracked.record.road_tracks, 2);
  EXPECT_EQ(tracked.road_mask.data, road.data);

  TrackedFrame without;
  without.frontend.observations = tracked.frontend.observations;
  SetRoadMask(cv::Mat(), &without);
  EXPECT_EQ(without.record.road_mask_px, -1);
  EXPECT_EQ(without.record.road_tracks, -1);
}

TEST(RunSummary, CountsTheKeyframesAndTheirRoadAlignments) {
  RunSummary summary;
  FrameRecord record;
  summary.Add(record);
  record.keyframe = true;
  record.bundle_adjustment_ms = 40.0;
  summary.Add(record);
  record.road_aligned = true;
  summary.Add(record);
  EXPECT_EQ(summary.keyframes, 2u);
  EXPECT_EQ(summary.road_aligned_keyframes, 1u);
  EXPECT_NE(summary.Format().find(
                "Keyframes: 2 (the road alignment converged on 1 of their pairs); bundle "
                "adjustment ms per keyframe: median 40.0"),
            std::string::npos)
      << summary.Format();
}

}  // namespace
}  // namespace roadscale
