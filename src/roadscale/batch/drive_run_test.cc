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

TEST(DriveFingerprintTest, ChangesWithArgumentsAndConfigContentsButNotTheOutputFolder) {
  TempDir dir;
  BatchDrive drive;
  drive.name = "a";
  drive.kitti = "/data/seq";
  drive.config = WriteTextFile(dir.File("run.yaml"), "Scale:\n  filter_window: 5\n");
  const std::string first = DriveFingerprint(drive);
  EXPECT_EQ(first.size(), 16U);
  EXPECT_EQ(DriveFingerprint(drive), first);

  BatchDrive other_frames = drive;
  other_frames.frames = "0:10";
  EXPECT_NE(DriveFingerprint(other_frames), first);

  BatchDrive renamed = drive;  // the name is the output folder, not part of the run
  renamed.name = "b";
  EXPECT_EQ(DriveFingerprint(renamed), first);

  WriteTextFile(drive.config, "Scale:\n  filter_window: 7\n");
  EXPECT_NE(DriveFingerprint(drive), first);
}

}  // namespace
}  // namespace roadscale::batch
