// The Odometry facade against RunPipeline reading the same rendered drive from its files:
// the same poses to the byte. Rendering makes it slow (label `slow`).
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/odometry/odometry.h"
#include "roadscale/pipeline/road_scale_source.h"
#include "roadscale/segmentation/label_image_segmenter.h"
#include "roadscale/synth/scene_writer.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/testing/temp_dir.h"

namespace roadscale {
namespace {

std::unique_ptr<LabelImageSegmenter> LabelsIn(const std::string& folder) {
  SegmentationModel model;
  model.yaml_path = folder;
  model.backend = SegmentationBackend::kLabelImages;
  model.label_images.folder = folder;
  model.label_images.ids = LabelIdSpace::kTrainIds;
  return std::make_unique<LabelImageSegmenter>(model, MaskOptions());
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
  const auto segmenter = LabelsIn(labels);
  Odometry odometry(options, {segmenter.get()},
                    [&](const FrameRecord&, const Rigid3d& world_from_cam) {
                      rows += FormatKittiRow(world_from_cam) + "\n";
                    });
  const auto source = OpenFrameSource(source_options);
  Frame frame;
  while (source->Next(&frame)) odometry.Track(frame.image, frame.timestamp, frame.path);
  EXPECT_EQ(odometry.Finish().summary.frames, 40u);
  EXPECT_EQ(rows, testing::ReadFileBytes(out + "/poses_kitti.txt"));
}

INSTANTIATE_TEST_SUITE_P(Threads, OdometrySynthetic, ::testing::Bool());

}  // namespace
}  // namespace roadscale
