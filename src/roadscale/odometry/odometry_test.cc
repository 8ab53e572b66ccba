#include "roadscale/odometry/odometry.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

OdometryOptions KittiCameraOptions() {
  OdometryOptions options;
  options.camera.camera = KittiOdometryCamera();
  options.camera.h0 = 1.65;
  return options;
}

cv::Mat Black(const OdometryOptions& options) {
  return cv::Mat(options.camera.camera.height, options.camera.camera.width, CV_8UC1, cv::Scalar(0));
}

TEST(Odometry, RejectsABadFrameAndTakesTheNext) {
  const OdometryOptions options = KittiCameraOptions();
  std::vector<size_t> frames;
  Odometry odometry(options, {}, [&](const FrameRecord& record, const Rigid3d&) {
    frames.push_back(record.index);
  });
  EXPECT_THROW(odometry.Track(cv::Mat(), 0.0), Error);
  EXPECT_THROW(odometry.Track(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), 0.0), Error);
  EXPECT_THROW(odometry.Track(cv::Mat(Black(options).size(), CV_32FC1, cv::Scalar(0)), 0.0), Error);
  odometry.Track(Black(options), 0.0);
  EXPECT_THROW(odometry.Track(Black(options), 0.0), Error);  // not after the previous frame
  odometry.Track(Black(options), 0.1);
  const PipelineRunResult result = odometry.Finish();
  EXPECT_EQ(result.summary.frames, 2u);
  EXPECT_EQ(frames, (std::vector<size_t>{0, 1}));
  EXPECT_THROW(odometry.Track(Black(options), 0.2), Error);  // finished
}

// A segmenter that fails on one frame, as a network would on a corrupt input.
class FailingSegmenter : public Segmenter {
 public:
  explicit FailingSegmenter(const std::string& failing_frame) : failing_frame_(failing_frame) {}
  SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) override {
    if (frame_name == failing_frame_) throw Error("frame " + frame_name + ": made to fail");
    return no_segmentation_.Segment(image, frame_name);
  }
  std::string Description() const override { return "fails on " + failing_frame_; }

 private:
  std::string failing_frame_;
  NoSegmenter no_segmentation_;
};

TEST(Odometry, TheErrorThatStopsItReachesTheCallerWithTheFramesBeforeIt) {
  const OdometryOptions options = KittiCameraOptions();
  FailingSegmenter segmenter("000003");
  std::vector<size_t> frames;
  Odometry odometry(options, {&segmenter}, [&](const FrameRecord& record, const Rigid3d&) {
    frames.push_back(record.index);
  });
  std::string message;
  try {
    // Track throws once the odometry has stopped, or Finish does.
    for (int i = 0; i < 20; ++i) odometry.Track(Black(options), 0.1 * i);
    odometry.Finish();
  } catch (const Error& error) {
    message = error.what();
  }
  EXPECT_EQ(message, "frame 000003: made to fail");
  EXPECT_EQ(frames, (std::vector<size_t>{0, 1, 2}));
  EXPECT_THROW(odometry.Finish(), Error);
}

TEST(OdometryOptions, RejectsACameraWithoutHeight) {
  OdometryOptions options = KittiCameraOptions();
  options.camera.h0 = 0.0;
  EXPECT_THROW(Odometry(options, {}, nullptr), Error);
}

}  // namespace
}  // namespace roadscale
