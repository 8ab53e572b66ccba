// The Odometry facade in frame-to-frame mode (Mapping: {mode: frame_to_frame}) on a short
// rendered drive held in memory: there each frame's provisional pose is its final pose, handed
// out as the frame goes out, also for the frames that waited for the first scale.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/odometry/odometry.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/testing/late_oracle.h"

namespace roadscale {
namespace {

constexpr size_t kFrames = 12;
constexpr size_t kFirstScaled = 5;  // the scale comes with the fifth step

struct RenderedDrive {
  CameraSetup camera;
  std::vector<cv::Mat> images;  // grey
  std::vector<double> timestamps;
  Trajectory truth;
};

// An urban drive's first frames, rendered once for every test here.
const RenderedDrive& Drive() {
  static const RenderedDrive drive = [] {
    synth::SyntheticScene scene(synth::PresetSceneOptions("urban"), kFrames);
    RenderedDrive rendered;
    rendered.camera.camera = scene.options().image.camera;
    rendered.camera.h0 = scene.options().vehicle.h0;
    for (size_t k = 0; k < kFrames; ++k) {
      const int index = static_cast<int>(k);
      rendered.images.push_back(scene.Render(index, /*colour=*/false).images.grey);
      rendered.timestamps.push_back(scene.Time(index));
      rendered.truth.world_from_cam.push_back(scene.WorldFromCam(index));
    }
    return rendered;
  }();
  return drive;
}

// What the two callbacks received, in the order they were called.
struct Received {
  std::vector<ProvisionalPose> provisional;
  std::vector<FrameRecord> records;
  std::vector<Rigid3d> final_poses;
  std::vector<std::pair<char, size_t>> calls;  // 'p' provisional or 'f' final, and the frame
};

// The drive through an Odometry in frame-to-frame mode whose step lengths are the true ones
// from kFirstScaled on.
Received RunDrive(bool threaded, int max_frames_before_first_scale) {
  const RenderedDrive& drive = Drive();
  OdometryOptions options;
  options.camera = drive.camera;
  options.pipeline.mapping.mode = MappingOptions::Mode::kFrameToFrame;
  options.pipeline.max_frames_before_first_scale = max_frames_before_first_scale;
  options.run.threaded = threaded;
  testing::LateOracle scale(drive.truth, kFirstScaled);
  Received received;
  Odometry odometry(
      options, {},
      [&](const FrameRecord& record, const Rigid3d& world_from_cam) {
        received.records.push_back(record);
        received.final_poses.push_back(world_from_cam);
        received.calls.emplace_back('f', record.index);
      },
      &scale,
      [&](const ProvisionalPose& pose) {
        received.provisional.push_back(pose);
        received.calls.emplace_back('p', pose.index);
      });
  for (size_t k = 0; k < kFrames; ++k) odometry.Track(drive.images[k], drive.timestamps[k]);
  EXPECT_EQ(odometry.Finish().summary.frames, kFrames);
  return received;
}

// One provisional pose a frame, in order, with its timestamp, handed out just before the
// frame's final pose and equal to it to the bit; metric where the final record has a scale.
void ExpectProvisionalPosesAreTheFinalOnes(const Received& received) {
  ASSERT_EQ(received.provisional.size(), kFrames);
  ASSERT_EQ(received.final_poses.size(), kFrames);
  for (size_t k = 0; k < kFrames; ++k) {
    const ProvisionalPose& provisional = received.provisional[k];
    EXPECT_EQ(provisional.index, k);
    EXPECT_EQ(provisional.timestamp, Drive().timestamps[k]) << k;
    EXPECT_EQ(received.calls[2 * k], std::make_pair('p', k));
    EXPECT_EQ(received.calls[2 * k + 1], std::make_pair('f', k));
    EXPECT_TRUE(provisional.world_from_cam.matrix() == received.final_poses[k].matrix()) << k;
    const std::string& status = received.records[k].status;
    EXPECT_EQ(provisional.metric, status != "first" && status != "unscaled") << k << status;
  }
}

// "first", then `before_scale` until the scale comes, then "ok".
std::vector<std::string> ExpectedStatuses(const std::string& before_scale) {
  std::vector<std::string> statuses(kFrames, "ok");
  statuses[0] = "first";
  for (size_t k = 1; k < kFirstScaled; ++k) statuses[k] = before_scale;
  return statuses;
}

std::vector<std::string> Statuses(const Received& received) {
  std::vector<std::string> statuses;
  for (const FrameRecord& record : received.records) statuses.push_back(record.status);
  return statuses;
}

class OdometryFrameToFrame : public ::testing::TestWithParam<bool> {};

// The frames before the first scale wait for it and go out with it, back-filled and metric.
TEST_P(OdometryFrameToFrame, WaitingFramesGetTheirProvisionalPoseWithTheFirstScale) {
  const Received received = RunDrive(GetParam(), /*max_frames_before_first_scale=*/100);
  ExpectProvisionalPosesAreTheFinalOnes(received);
  EXPECT_EQ(Statuses(received), ExpectedStatuses("backfilled"));
}

// Waiting for two frames only: the frames before the scale go out unscaled, not metric.
TEST_P(OdometryFrameToFrame, UnscaledFramesGetProvisionalPosesThatAreNotMetric) {
  const Received received = RunDrive(GetParam(), /*max_frames_before_first_scale=*/2);
  ExpectProvisionalPosesAreTheFinalOnes(received);
  EXPECT_EQ(Statuses(received), ExpectedStatuses("unscaled"));
}

INSTANTIATE_TEST_SUITE_P(Threads, OdometryFrameToFrame, ::testing::Bool());

}  // namespace
}  // namespace roadscale
