#include "roadscale/pipeline/segmentation_schedule.h"

#include <vector>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

#include <Eigen/Geometry>

namespace roadscale {
namespace {

PinholeCamera Camera() {
  PinholeCamera camera;
  camera.fx = camera.fy = 700.0;
  camera.cx = 600.0;
  camera.cy = 180.0;
  camera.width = 1200;
  camera.height = 360;
  return camera;
}

// A frame whose 100 tracks (ids 0..99, on a grid) have moved `shift_px` to the right of
// where they started, seen with the frontend's rotation `rotation` from the frame before.
FrontendFrame Frame(int index, double shift_px, MotionStatus status,
                    const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity(),
                    int tracks = 100) {
  FrontendFrame frame;
  frame.frame_index = index;
  frame.motion.status = index == 0 ? MotionStatus::kFirstFrame : status;
  frame.motion.rotation = rotation;
  for (int id = 0; id < tracks; ++id) {
    const Eigen::Vector2d start(100.0 + 10.0 * (id % 10), 100.0 + 10.0 * (id / 10));
    frame.observations.push_back({id, start + Eigen::Vector2d(shift_px, 0.0)});
  }
  return frame;
}

std::vector<int> Segmented(SegmentationSchedule& schedule, const std::vector<FrontendFrame>& frames,
                           int failing_frame = -1) {
  std::vector<int> out;
  for (const FrontendFrame& frame : frames) {
    if (schedule.Decide(frame, frame.frame_index == failing_frame)) {
      out.push_back(frame.frame_index);
    }
  }
  return out;
}

TEST(SegmentationSchedule, SegmentsEachTimeTheParallaxReachesTheKeyframeThreshold) {
  // 4 px of parallax a frame: 10 px is reached every third frame after a segmented one.
  std::vector<FrontendFrame> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(Frame(i, 4.0 * i, MotionStatus::kOk));
  SegmentationSchedule schedule(Camera(), KeyframeSelectorOptions());
  EXPECT_EQ(Segmented(schedule, frames), (std::vector<int>{0, 3, 6, 9}));
}

TEST(SegmentationSchedule, AStationaryCarIsNotSegmentedAgainUntilTheFrameGap) {
  KeyframeSelectorOptions options;
  options.max_frame_gap = 5;
  std::vector<FrontendFrame> frames;
  for (int i = 0; i < 12; ++i) frames.push_back(Frame(i, 0.0, MotionStatus::kOk));
  SegmentationSchedule schedule(Camera(), options);
  EXPECT_EQ(Segmented(schedule, frames), (std::vector<int>{0, 5, 10}));
  // Stationary frames never are (the keyframe rule: they add no baseline).
  for (int i = 0; i < 12; ++i) frames[i] = Frame(i, 0.0, MotionStatus::kStationary);
  SegmentationSchedule stationary(Camera(), options);
  EXPECT_EQ(Segmented(stationary, frames), (std::vector<int>{0}));
}

TEST(SegmentationSchedule, ImageMotionOfARotationIsNoParallax) {
  // Turning 0.5 deg a frame about the vertical axis moves the image ~6 px a frame; the
  // rotation explains all of it.
  const double angle = 0.5 * M_PI / 180.0;
  const Eigen::Matrix3d step = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).matrix();
  const PinholeCamera camera = Camera();
  std::vector<FrontendFrame> frames;
  Eigen::Matrix3d total = Eigen::Matrix3d::Identity();
  for (int i = 0; i < 8; ++i) {
    FrontendFrame frame = Frame(i, 0.0, MotionStatus::kPureRotation, step);
    for (TrackObservation& observation : frame.observations) {
      observation.pixel = camera.Project(total * camera.Unproject(observation.pixel));
    }
    frames.push_back(frame);
    total = step * total;
  }
  SegmentationSchedule schedule(camera, KeyframeSelectorOptions());
  EXPECT_EQ(Segmented(schedule, frames), (std::vector<int>{0}));
}

TEST(SegmentationSchedule, LostTracksAndAFailedCarrySegment) {
  std::vector<FrontendFrame> frames;
  for (int i = 0; i < 6; ++i) frames.push_back(Frame(i, 1.0 * i, MotionStatus::kOk));
  frames[2] = Frame(2, 2.0, MotionStatus::kOk, Eigen::Matrix3d::Identity(), 40);  // 60 % lost
  SegmentationSchedule schedule(Camera(), KeyframeSelectorOptions());
  EXPECT_EQ(Segmented(schedule, frames, 4), (std::vector<int>{0, 2, 4}));
}

TEST(SegmentationSchedule, OptionsAreChecked) {
  SegmentationScheduleOptions options;
  EXPECT_NO_THROW(options.Check());
  options.latency_frames = 0;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_EQ(ParseSegmentationScheduleMode("every_frame"), SegmentationScheduleMode::kEveryFrame);
  EXPECT_EQ(SegmentationScheduleModeName(SegmentationScheduleMode::kKeyframes), "keyframes");
  EXPECT_THROW(ParseSegmentationScheduleMode("sometimes"), Error);
}

}  // namespace
}  // namespace roadscale
