#include "roadscale/batch/drive_run.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"

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
  const std::string first = DriveFingerprint(drive, "1.0.0");
  EXPECT_EQ(first.size(), 16U);
  EXPECT_EQ(DriveFingerprint(drive, "1.0.0"), first);

  BatchDrive other_frames = drive;
  other_frames.frames = "0:10";
  EXPECT_NE(DriveFingerprint(other_frames, "1.0.0"), first);

  BatchDrive renamed = drive;  // the name is the output folder, not part of the run
  renamed.name = "b";
  EXPECT_EQ(DriveFingerprint(renamed, "1.0.0"), first);

  // Another roadscale may give other outputs: a resume with it reruns (issue 30).
  EXPECT_NE(DriveFingerprint(drive, "1.0.1"), first);

  WriteTextFile(drive.config, "Scale:\n  filter_window: 7\n");
  EXPECT_NE(DriveFingerprint(drive, "1.0.0"), first);
}

}  // namespace
}  // namespace roadscale::batch
