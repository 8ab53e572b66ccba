#include "roadscale/pipeline/run_output_files.h"

#include <string>

#include <gtest/gtest.h>

#include "roadscale/io/trajectory_io.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(RunOutputFiles, WritesEachFramesPoseRowsAndRecord) {
  testing::TempDir dir;
  const std::string out = dir.File("run");
  {
    RunOutputFiles files(out, "a,b");
    FrameRecord first;
    first.index = 0;
    first.timestamp = 0.5;
    first.scale_diagnostics_csv = "1,2";
    files.Write(first, Rigid3d::Identity());
    FrameRecord second = first;
    second.index = 1;
    second.timestamp = 0.6;
    second.scale_diagnostics_csv.clear();  // a frame the scale source did not see
    Rigid3d ahead = Rigid3d::Identity();
    ahead.translation() = Eigen::Vector3d(0.0, 0.0, 2.0);
    files.Write(second, ahead);
  }
  const Trajectory poses = ReadKittiTrajectory(out + "/poses_kitti.txt");
  ASSERT_EQ(poses.world_from_cam.size(), 2u);
  EXPECT_DOUBLE_EQ(poses.world_from_cam[1].translation().z(), 2.0);
  const Trajectory tum = ReadTumTrajectory(out + "/poses_tum.txt");
  ASSERT_EQ(tum.timestamps.size(), 2u);
  EXPECT_DOUBLE_EQ(tum.timestamps[1], 0.6);

  const std::string csv = testing::ReadFileBytes(out + "/frames.csv");
  const std::string header = FrameRecordCsvHeader() + ",a,b\n";
  ASSERT_EQ(csv.substr(0, header.size()), header);
  FrameRecord first;
  first.timestamp = 0.5;
  FrameRecord second;
  second.index = 1;
  second.timestamp = 0.6;
  EXPECT_EQ(csv.substr(header.size()),
            FormatFrameRecordCsv(first) + ",1,2\n" + FormatFrameRecordCsv(second) + ",,\n");
}

TEST(RunOutputFiles, EmptiesTheFilesOfAnEarlierRun) {
  testing::TempDir dir;
  const std::string out = dir.File("run");
  {
    RunOutputFiles files(out, "");
    files.Write(FrameRecord(), Rigid3d::Identity());
  }
  RunOutputFiles again(out, "");
  EXPECT_EQ(testing::ReadFileBytes(out + "/poses_kitti.txt"), "");
  EXPECT_EQ(testing::ReadFileBytes(out + "/frames.csv"), FrameRecordCsvHeader() + "\n");
}

TEST(RunOutputFiles, RejectsAnOutputFolderThatCannotBeCreated) {
  testing::TempDir dir;
  const std::string blocker = testing::WriteTextFile(dir.File("file"), "x");
  EXPECT_THROW(RunOutputFiles(blocker + "/out", ""), Error);
}

}  // namespace
}  // namespace roadscale
