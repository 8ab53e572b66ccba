#include "roadscale/io/trajectory_io.h"

#include <csignal>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using testing::TempDir;
using testing::WriteTextFile;

Trajectory ExampleTrajectory() {
  Trajectory trajectory;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.1 * i + 1e-13, Eigen::Vector3d(0.2, 1.0, 0.1).normalized())
            .toRotationMatrix();
    trajectory.world_from_cam.push_back(
        MakeRigid3d(rotation, Eigen::Vector3d(0.1 * i, -0.02 * i, 1.0 / 3.0 * i)));
    trajectory.timestamps.push_back(0.1037359 * i);
  }
  return trajectory;
}

TEST(TrajectoryIo, KittiRoundTripIsExact) {
  TempDir dir;
  const Trajectory written = ExampleTrajectory();
  WriteKittiTrajectory(dir.File("poses.txt"), written);
  const Trajectory read = ReadKittiTrajectory(dir.File("poses.txt"));
  ASSERT_EQ(read.size(), written.size());
  EXPECT_FALSE(read.HasTimestamps());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read.world_from_cam[i].matrix(), written.world_from_cam[i].matrix()) << i;
  }
}

// A full disk left gt_poses_kitti.txt cut mid-row (issue 30, defect 10): a write that fails
// (here at the 1 KiB file size limit, as on a full disk) leaves the previous file whole.
TEST(TrajectoryIo, AFailedWriteLeavesThePreviousFileWhole) {
  TempDir dir;
  const std::string path = dir.File("gt_poses_kitti.txt");
  WriteKittiTrajectory(path, ExampleTrajectory());
  const std::string before = testing::ReadFileBytes(path);
  Trajectory longer;
  for (int i = 0; i < 50; ++i) {
    longer.world_from_cam.push_back(ExampleTrajectory().world_from_cam[static_cast<size_t>(i % 4)]);
  }
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{1024, 1024};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      WriteKittiTrajectory(path, longer);
    } catch (const Error&) {
      _exit(3);
    }
    _exit(4);
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << "the write did not fail";
  EXPECT_EQ(testing::ReadFileBytes(path), before);
}

TEST(TrajectoryIo, TumRoundTripKeepsTimestampsAndPoses) {
  TempDir dir;
  const Trajectory written = ExampleTrajectory();
  WriteTumTrajectory(dir.File("poses_tum.txt"), written);
  const Trajectory read = ReadTumTrajectory(dir.File("poses_tum.txt"));
  ASSERT_EQ(read.size(), written.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read.timestamps[i], written.timestamps[i]);
    EXPECT_TRUE(read.world_from_cam[i].isApprox(written.world_from_cam[i], 1e-15)) << i;
  }
}

TEST(TrajectoryIo, ToleratesCommentsAndBlankLines) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("t.txt"),
                                         "# header\n\n1 0 0 0 0 1 0 0 0 0 1 0\n   \n"
                                         "1 0 0 1 0 1 0 2 0 0 1 3\n");
  const Trajectory read = ReadKittiTrajectory(path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read.world_from_cam[1].translation(), Eigen::Vector3d(1, 2, 3));
}

TEST(TrajectoryIo, MalformedRowsNameFileAndLine) {
  TempDir dir;
  const std::string short_row =
      WriteTextFile(dir.File("short.txt"), "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n");
  try {
    ReadKittiTrajectory(short_row);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              short_row + ":2: expected 12 numbers (a row-major 3x4 pose), found 11");
  }
  const std::string bad_tum = WriteTextFile(dir.File("bad.tum"), "0.0 1 2 3 0 0 0 1\n0.1 1 2 x\n");
  EXPECT_THROW(ReadTumTrajectory(bad_tum), Error);
  const std::string backwards =
      WriteTextFile(dir.File("back.tum"), "0.2 1 2 3 0 0 0 1\n0.1 1 2 3 0 0 0 1\n");
  EXPECT_THROW(ReadTumTrajectory(backwards), Error);
  EXPECT_THROW(ReadKittiTrajectory(dir.File("does_not_exist.txt")), Error);
}

std::string ErrorOf(const std::string& path, TrajectoryFormat format) {
  try {
    ReadTrajectory(path, format);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(TrajectoryIo, KittiRowsMustBeRigid) {
  TempDir dir;
  const std::string identity = "1 0 0 0 0 1 0 0 0 0 1 0\n";
  const auto error_of_second_row = [&](const std::string& name, const std::string& row) {
    return ErrorOf(WriteTextFile(dir.File(name), identity + row + "\n"), TrajectoryFormat::kKitti);
  };
  const std::string not_rotation = ":2: the 3x3 part is not a rotation";
  EXPECT_EQ(error_of_second_row("zero.txt", "0 0 0 1 0 0 0 2 0 0 0 3"),
            dir.File("zero.txt") + not_rotation +
                " (max |R^T R - I| = 1, det(R) = 0; expected below 0.01 and det > 0)");
  EXPECT_THAT(error_of_second_row("scaled.txt", "1.1 0 0 1 0 1.1 0 2 0 0 1.1 3"),
              ::testing::HasSubstr(not_rotation));
  EXPECT_THAT(error_of_second_row("sheared.txt", "1 0.3 0 1 0 1 0 2 0 0 1 3"),
              ::testing::HasSubstr(not_rotation));
  // Orthogonal but mirrored: det -1.
  EXPECT_THAT(error_of_second_row("mirrored.txt", "-1 0 0 1 0 1 0 2 0 0 1 3"),
              ::testing::HasSubstr("det(R) = -1"));
  EXPECT_EQ(error_of_second_row("far.txt", "1 0 0 1e30 0 1 0 2 0 0 1 3"),
            dir.File("far.txt") + ":2: the position (1e+30, 2, 3) is beyond 1e+08 m");
  // A rotation of 0.3 rad about y rounded to 3 decimals passes.
  EXPECT_EQ(error_of_second_row("rounded.txt", "0.955 0 0.296 1 0 1 0 2 -0.296 0 0.955 3"),
            "no error");
}

TEST(TrajectoryIo, TumQuaternionsMustHaveUnitLength) {
  TempDir dir;
  const std::string zero = WriteTextFile(dir.File("zero.tum"), "0 1 2 3 0 0 0 0\n");
  EXPECT_THAT(ErrorOf(zero, TrajectoryFormat::kTum),
              ::testing::HasSubstr(zero + ":1: the quaternion (qx qy qz qw) has length 0.000000"));
  const std::string half = WriteTextFile(dir.File("half.tum"), "0 1 2 3 0 0 0 0.5\n");
  EXPECT_THAT(ErrorOf(half, TrajectoryFormat::kTum), ::testing::HasSubstr("has length 0.5"));
  const std::string rounded =
      WriteTextFile(dir.File("ok.tum"), "0 1 2 3 0.0998 0 0 0.995\n");  // |q| = 0.99999
  EXPECT_EQ(ErrorOf(rounded, TrajectoryFormat::kTum), "no error");
}

TEST(TrajectoryIo, FormatFromTheFirstRow) {
  TempDir dir;
  TrajectoryFormat format = TrajectoryFormat::kKitti;
  const std::string tum =
      WriteTextFile(dir.File("a.txt"), "# comment\n\n0 1 2 3 0 0 0 1\n0.1 1 2 4 0 0 0 1\n");
  EXPECT_EQ(ReadTrajectoryOfEitherFormat(tum, &format).size(), 2u);
  EXPECT_EQ(format, TrajectoryFormat::kTum);
  const std::string kitti = WriteTextFile(dir.File("b.txt"), "1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_EQ(ReadTrajectoryOfEitherFormat(kitti, &format).size(), 1u);
  EXPECT_EQ(format, TrajectoryFormat::kKitti);
  EXPECT_THROW(ReadTrajectoryOfEitherFormat(WriteTextFile(dir.File("c.txt"), "1 2 3\n"), &format),
               Error);
  EXPECT_THROW(ReadTrajectoryOfEitherFormat(WriteTextFile(dir.File("d.txt"), "# none\n"), &format),
               Error);
}

TEST(TrajectoryIo, ReadsSharedKittiGroundTruth) {
  ROADSCALE_REQUIRE_SHARED("kitti/poses/00.txt");
  const Trajectory gt = ReadKittiTrajectory(testing::SharedPath("kitti/poses/00.txt").string());
  ASSERT_EQ(gt.size(), 4541u);
  EXPECT_TRUE(gt.world_from_cam[0].matrix().isApprox(Eigen::Matrix4d::Identity(), 1e-6))
      << "KITTI writes frame 0 as the identity with 7 digits";
}

}  // namespace
}  // namespace roadscale
