#include "roadscale/pipeline/sequential_pipeline.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/mapping/keyframe_backend.h"
#include "roadscale/pipeline/road_scale_source.h"

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

// frames.csv is the per-frame columns, then the scale source's or the back end's: a reader
// that looks columns up by name (Python's csv.DictReader) must find each once.
TEST(SequentialPipeline, FramesCsvNamesEachColumnOnce) {
  const auto duplicates = [](const std::string& header) {
    std::vector<std::string> names;
    std::stringstream stream(header);
    for (std::string name; std::getline(stream, name, ',');) names.push_back(name);
    std::sort(names.begin(), names.end());
    std::vector<std::string> twice;
    for (size_t i = 1; i < names.size(); ++i) {
      if (names[i] == names[i - 1]) twice.push_back(names[i]);
    }
    return twice;
  };
  const PinholeCamera camera{718.856, 718.856, 607.19, 185.22, 1241, 376};
  const RoadScaleSource road(camera, ScaleEstimatorOptions());
  EXPECT_TRUE(duplicates(FrameRecordCsvHeader() + "," + road.DiagnosticsCsvHeader()).empty());
  EXPECT_TRUE(duplicates(FrameRecordCsvHeader() + "," + MappedFrameCsvHeader()).empty());
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
