#include "roadscale/batch/drive_run.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

using roadscale::testing::TempDir;
using roadscale::testing::WriteTextFile;
using ::testing::ElementsAre;

TEST(RunArgumentsTest, RunsOptionsInAFixedOrderThenOut) {
  BatchDrive drive;
  drive.name = "a";
  drive.kitti = "/data/seq";
  drive.frames = "0:20";
  drive.h0 = 1.65;
  drive.no_segmentation = true;
  EXPECT_THAT(RunArguments(drive, "/out/a"),
              ElementsAre("run", "--kitti", "/data/seq", "--no-segmentation", "--h0", "1.65",
                          "--frames", "0:20", "--out", "/out/a"));
}

TEST(RunArgumentsTest, PassesEveryOptionOfTheRun) {
  RunRequest run;
  run.images = "/data/frames";
  run.camera = "/data/cam.yaml";
  run.config = "/data/run.yaml";
  run.model = "/data/model.yaml";
  run.scale = "oracle";
  run.detector = "orb";
  run.h0 = 1.5;
  run.frames = "5:";
  run.sequential = true;
  EXPECT_THAT(RunArguments(run, "/out/b"),
              ElementsAre("run", "--images", "/data/frames", "--camera", "/data/cam.yaml",
                          "--config", "/data/run.yaml", "--model", "/data/model.yaml", "--scale",
                          "oracle", "--detector", "orb", "--h0", "1.5", "--frames",
                          "5:", "--sequential", "--out", "/out/b"));
  RunRequest other;
  other.video = "/data/drive.mp4";
  other.labels = "/data/labels";
  EXPECT_THAT(RunArguments(other, "/out/c"),
              ElementsAre("run", "--video", "/data/drive.mp4", "--labels", "/data/labels", "--out",
                          "/out/c"));
}

TEST(DriveFingerprintTest, ChangesWithArgumentsAndConfigContentsButNotTheOutputFolder) {
  TempDir dir;
  BatchDrive drive;
  drive.name = "a";
  drive.kitti = "/data/seq";
  drive.config = WriteTextFile(dir.File("run.yaml"), "Scale:\n  filter_window: 5\n");
  const std::string first = DriveFingerprint(drive, "1.0.0", "");
  EXPECT_EQ(first.size(), 16U);
  EXPECT_EQ(DriveFingerprint(drive, "1.0.0", ""), first);

  BatchDrive other_frames = drive;
  other_frames.frames = "0:10";
  EXPECT_NE(DriveFingerprint(other_frames, "1.0.0", ""), first);

  BatchDrive renamed = drive;  // the name is the output folder, not part of the run
  renamed.name = "b";
  EXPECT_EQ(DriveFingerprint(renamed, "1.0.0", ""), first);

  // Another roadscale may give other outputs: a resume with it reruns (issue 30).
  EXPECT_NE(DriveFingerprint(drive, "1.0.1", ""), first);

  WriteTextFile(drive.config, "Scale:\n  filter_window: 7\n");
  EXPECT_NE(DriveFingerprint(drive, "1.0.0", ""), first);
}

// The network's weights decide the masks as much as the config does: new weights under the
// same file name rerun the drive (issue 30), whether the model is the drive's, its config's
// or the default; with label images no model is loaded and the weights do not count.
TEST(DriveFingerprintTest, ChangesWithTheWeightsOfTheModelTheRunLoads) {
  TempDir dir;
  const std::string weights = WriteTextFile(dir.File("net.onnx"), "weights 1");
  const std::string model =
      WriteTextFile(dir.File("net.yaml"),
                    "backend: onnx\nfile: net.onnx\ninput_size: [64, 32]\nchannel_order: rgb\n"
                    "num_classes: 20\n");
  BatchDrive drive;
  drive.name = "a";
  drive.kitti = "/data/seq";

  BatchDrive named = drive;
  named.model = model;
  BatchDrive in_config = drive;
  in_config.config = WriteTextFile(dir.File("run.yaml"), "Segmentation:\n  model: " + model + "\n");
  BatchDrive labelled = drive;
  labelled.labels = dir.File("labels");

  std::vector<std::string> before;
  for (const BatchDrive* d : {&named, &in_config, &drive, &labelled}) {
    before.push_back(DriveFingerprint(*d, "1.0.0", model));
  }
  WriteTextFile(weights, "weights 2");
  EXPECT_NE(DriveFingerprint(named, "1.0.0", model), before[0]);
  EXPECT_NE(DriveFingerprint(in_config, "1.0.0", model), before[1]);
  EXPECT_NE(DriveFingerprint(drive, "1.0.0", model), before[2]);
  EXPECT_EQ(DriveFingerprint(labelled, "1.0.0", model), before[3]);

  EXPECT_EQ(DriveModelFile(named, "default.yaml"), model);
  EXPECT_EQ(DriveModelFile(in_config, "default.yaml"), model);
  EXPECT_EQ(DriveModelFile(drive, "default.yaml"), "default.yaml");
  EXPECT_EQ(DriveModelFile(labelled, "default.yaml"), "");
}

// Run goes without segmentation when the default model is missing; so does the fingerprint,
// while a model the drive names must be there.
TEST(DriveFingerprintTest, AMissingDefaultModelIsNoModelAndANamedOneAnError) {
  TempDir dir;
  BatchDrive drive;
  drive.name = "a";
  drive.kitti = "/data/seq";
  EXPECT_EQ(DriveFingerprint(drive, "1.0.0", dir.File("missing.yaml")).size(), 16U);
  drive.model = dir.File("missing.yaml");
  EXPECT_THROW(DriveFingerprint(drive, "1.0.0", ""), Error);
}

}  // namespace
}  // namespace roadscale::batch
