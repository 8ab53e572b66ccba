// The Odometry facade against RunPipeline reading the same rendered drive from its files:
// the same poses to the byte. Rendering makes it slow (label `slow`).
#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/odometry/odometry.h"
#include "roadscale/odometry/odometry_config.h"
#include "roadscale/pipeline/road_scale_source.h"
#include "roadscale/synth/scene_writer.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/testing/temp_dir.h"

namespace roadscale {
namespace {

// The label images of `folder` as `roadscale run --labels` reads them.
std::unique_ptr<Segmenter> LabelsIn(const std::string& folder) {
  RunConfig config;
  config.labels = folder;
  return std::move(MakeConfigSegmenters(config).front());
}

class OdometrySynthetic : public ::testing::TestWithParam<bool> {};

TEST_P(OdometrySynthetic, GivesThePosesOfARunOnTheSameFrames) {
  testing::TempDir dir;
  synth::SyntheticScene scene(synth::PresetSceneOptions("urban"), 40);
  synth::SceneWriterOptions writer;
  writer.out_dir = dir.path().string();
  synth::WriteSyntheticSequence(scene, writer);
  FrameSourceOptions source_options;
  source_options.input = (dir.path() / "sequences" / "00").string();
  source_options.type = FrameSourceType::kKitti;
  const std::string labels = source_options.input + "/semantic";

  OdometryOptions options;
  options.run.threaded = GetParam();
  const std::string out = dir.File("run");
  {
    const auto source = OpenFrameSource(source_options);
    options.camera = source->camera();
    options.pipeline.road_selection.camera_height = options.camera.h0;
    const auto segmenter = LabelsIn(labels);
    RoadScaleSource road(options.camera.camera, options.pipeline.road_selection);
    RunPipeline(*source, {segmenter.get()}, road, options.pipeline, out, options.run);
  }

  std::string rows;
  std::vector<Rigid3d> final_poses;
  std::vector<ProvisionalPose> provisional;
  const auto segmenter = LabelsIn(labels);
  Odometry odometry(
      options, {segmenter.get()},
      [&](const FrameRecord&, const Rigid3d& world_from_cam) {
        rows += FormatKittiRow(world_from_cam) + "\n";
        final_poses.push_back(world_from_cam);
      },
      /*scale=*/nullptr, [&](const ProvisionalPose& pose) { provisional.push_back(pose); });
  const auto source = OpenFrameSource(source_options);
  Frame frame;
  std::vector<double> timestamps;
  while (source->Next(&frame)) {
    odometry.Track(frame.image, frame.timestamp, frame.path);
    timestamps.push_back(frame.timestamp);
  }
  EXPECT_EQ(odometry.Finish().summary.frames, 40u);
  // Taking the provisional poses changes nothing of the final ones.
  EXPECT_EQ(rows, testing::ReadFileBytes(out + "/poses_kitti.txt"));

  // One provisional pose a frame, in order, metric from the map's first scale on, and near the
  // frame's final pose: the window's adjustments move a localised frame by centimetres.
  ASSERT_EQ(provisional.size(), 40u);
  ASSERT_EQ(final_poses.size(), 40u);
  size_t metric = 0;
  double largest_offset_m = 0.0;
  for (size_t k = 0; k < provisional.size(); ++k) {
    EXPECT_EQ(provisional[k].index, k);
    EXPECT_EQ(provisional[k].timestamp, timestamps[k]);
    if (k > 0 && provisional[k - 1].metric) {
      EXPECT_TRUE(provisional[k].metric) << k;
    }
    if (!provisional[k].metric) continue;
    ++metric;
    largest_offset_m = std::max(
        largest_offset_m,
        (provisional[k].world_from_cam.translation() - final_poses[k].translation()).norm());
  }
  EXPECT_GE(metric, 20u);
  EXPECT_LT(largest_offset_m, 0.3);
  std::cout << metric << " metric provisional poses, at most " << largest_offset_m
            << " m from the final ones\n";
}

INSTANTIATE_TEST_SUITE_P(Threads, OdometrySynthetic, ::testing::Bool());

}  // namespace
}  // namespace roadscale
