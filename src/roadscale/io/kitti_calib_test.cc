#include "roadscale/io/kitti_calib.h"

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/error_of.h"
#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

#include <Eigen/LU>

namespace roadscale {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteTextFile;

using testing::ErrorOf;

const char* const kIdentityRow = " 1 0 0 0 0 1 0 0 0 0 1 0\n";

TEST(KittiCalib, WrittenFileReadsBackWithKittiStereoLayout) {
  TempDir dir;
  PinholeCamera camera = KittiOdometryCamera();
  camera.cx = 600.123456789;
  WriteKittiCalib(dir.File("calib.txt"), camera);
  const KittiCalib calib = ReadKittiCalib(dir.File("calib.txt"));
  ASSERT_TRUE(calib.has_P[0] && calib.has_P[1] && calib.has_P[2] && calib.has_P[3]);
  ASSERT_TRUE(calib.has_Tr);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(calib.P[i].leftCols<3>().isApprox(camera.K(), 1e-12)) << i;
  }
  EXPECT_EQ(calib.P[0].col(3), Eigen::Vector3d::Zero());
  EXPECT_EQ(calib.P[2].col(3), Eigen::Vector3d::Zero());
  // A right camera b metres to the right: P(0,3) = -fx * b.
  EXPECT_NEAR(calib.P[1](0, 3), -718.856 * 0.54, 1e-9);
  EXPECT_NEAR(calib.P[3](0, 3), -718.856 * 0.54, 1e-9);
  // Tr maps the velodyne's forward axis (x) to the camera's forward axis (z), left (y) to
  // -x (left of a right-pointing axis) and up (z) to -y (y points down).
  const Eigen::Matrix3d rotation = calib.Tr.leftCols<3>();
  EXPECT_EQ(rotation * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ());
  EXPECT_EQ(rotation * Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitX());
  EXPECT_EQ(rotation * Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitY());
  EXPECT_NEAR(rotation.determinant(), 1.0, 1e-15);

  const PinholeCamera read = ReadKittiCamera(dir.File("calib.txt"), 2, 1241, 376);
  EXPECT_NEAR(read.fx, camera.fx, 1e-12 * camera.fx);
  EXPECT_NEAR(read.cx, camera.cx, 1e-12 * camera.cx);
  EXPECT_NEAR(read.cy, camera.cy, 1e-12 * camera.cy);
  EXPECT_EQ(read.width, 1241);
  EXPECT_EQ(read.height, 376);
}

TEST(KittiCalib, WrittenRowsUseKittiNumberFormat) {
  TempDir dir;
  WriteKittiCalib(dir.File("calib.txt"), KittiOdometryCamera());
  std::ifstream file(dir.File("calib.txt"));
  std::string first_line;
  std::getline(file, first_line);
  EXPECT_EQ(first_line.substr(0, 44), "P0: 7.188560000000e+02 0.000000000000e+00 6.");
}

TEST(KittiCalib, RowWithElevenNumbersNamesFileAndLine) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("calib.txt"),
                                         std::string("P0:") + kIdentityRow +
                                             "P1: 1 0 0 0 0 1 0 0 0 0 1\n"  // 11 numbers
                                             "P2:" +
                                             kIdentityRow);
  EXPECT_THAT(ErrorOf([&] { ReadKittiCalib(path); }),
              HasSubstr(path + ":2: expected 12 numbers (a row-major 3x4 matrix) after 'P1:', "
                               "found 11"));
}

TEST(KittiCalib, MalformedRowsAreRejectedWithTheirLine) {
  TempDir dir;
  const std::string not_number = WriteTextFile(
      dir.File("a.txt"), std::string("P0:") + kIdentityRow + "Tr: 1 0 0 0 0 1 0 x 0 0 1 0\n");
  EXPECT_THAT(ErrorOf([&] { ReadKittiCalib(not_number); }),
              HasSubstr(not_number + ":2: expected a number, found 'x'"));
  const std::string no_key = WriteTextFile(dir.File("b.txt"), "\n1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THAT(ErrorOf([&] { ReadKittiCalib(no_key); }), HasSubstr(no_key + ":2: expected 'KEY:"));
  const std::string twice = WriteTextFile(
      dir.File("c.txt"), std::string("P0:") + kIdentityRow + "# comment\nP0:" + kIdentityRow);
  EXPECT_THAT(ErrorOf([&] { ReadKittiCalib(twice); }),
              HasSubstr(twice + ":3: 'P0:' appears twice"));
}

TEST(KittiCalib, UnknownKeysAreIgnored) {
  TempDir dir;
  const std::string path =
      WriteTextFile(dir.File("calib.txt"),
                    "calib_time: 09-Jan-2012 13:57:47\nP0: 700 0 320 0 0 710 240 0 0 0 1 0\n");
  const PinholeCamera camera = ReadKittiCamera(path, 0, 640, 480);
  EXPECT_EQ(camera.fx, 700.0);
  EXPECT_EQ(camera.fy, 710.0);
  EXPECT_EQ(camera.cx, 320.0);
  EXPECT_EQ(camera.cy, 240.0);
}

TEST(KittiCalib, MissingOrNonRectifiedRowIsRejected) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("calib.txt"),
                                         "P0: 700 0 320 0 0 700 240 0 0 0 1 0\n"
                                         "P1: 700 5 320 0 0 700 240 0 0 0 1 0\n");
  EXPECT_THAT(ErrorOf([&] { ReadKittiCamera(path, 2, 640, 480); }),
              HasSubstr(path + ": missing row 'P2:'"));
  EXPECT_THAT(ErrorOf([&] { ReadKittiCamera(path, 1, 640, 480); }),
              HasSubstr("'P1:' is not a rectified projection"));
  EXPECT_THAT(ErrorOf([&] { ReadKittiCamera(path, 0, 0, 480); }), HasSubstr("width/height"));
  EXPECT_THROW(ReadKittiCamera(dir.File("absent.txt"), 0, 640, 480), Error);
}

TEST(KittiCalib, TimesAreReadAndMustIncrease) {
  TempDir dir;
  const std::vector<double> times =
      ReadKittiTimes(WriteTextFile(dir.File("times.txt"), "0.000000e+00\n1.037359e-01\n\n"));
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[1], 0.1037359);

  const std::string backwards = WriteTextFile(dir.File("b.txt"), "0.0\n0.2\n0.1\n");
  EXPECT_THAT(ErrorOf([&] { ReadKittiTimes(backwards); }),
              HasSubstr(backwards + ":3: timestamps must increase"));
  const std::string two = WriteTextFile(dir.File("c.txt"), "0.0\n0.1 0.2\n");
  EXPECT_THAT(ErrorOf([&] { ReadKittiTimes(two); }), HasSubstr(two + ":2: expected one timestamp"));
  EXPECT_THAT(ErrorOf([&] { ReadKittiTimes(dir.File("absent.txt")); }),
              HasSubstr("cannot open timestamps file"));
}

TEST(KittiCalib, AByteOrderMarkIsSkippedAndADirectoryIsNamed) {
  TempDir dir;
  const std::string path =
      WriteTextFile(dir.File("calib.txt"), "\xEF\xBB\xBFP0: 700 0 600 0 0 700 180 0 0 0 1 0\n");
  const KittiCalib calib = ReadKittiCalib(path);
  EXPECT_TRUE(calib.has_P[0]);
  EXPECT_EQ(calib.P[0](0, 0), 700.0);
  EXPECT_THAT(
      ErrorOf([&] { ReadKittiCalib(dir.path().string()); }),
      HasSubstr(dir.path().string() + ": cannot open KITTI calibration file: is a directory"));
  EXPECT_THAT(ErrorOf([&] { ReadKittiTimes(dir.path().string()); }),
              HasSubstr(": cannot open timestamps file: is a directory"));
}

TEST(KittiCalibData, SharedSequence00) {
  ROADSCALE_REQUIRE_SHARED("kitti/sequences/00/calib.txt");
  const std::string path = testing::SharedPath("kitti/sequences/00/calib.txt").string();
  const KittiCalib calib = ReadKittiCalib(path);
  EXPECT_TRUE(calib.has_Tr);
  const PinholeCamera camera = KittiCameraFromCalib(calib, 0, 1241, 376, path);
  EXPECT_EQ(camera.fx, 718.856);
  EXPECT_EQ(camera.fy, 718.856);
  EXPECT_EQ(camera.cx, 607.1928);
  EXPECT_EQ(camera.cy, 185.2157);
  // KITTI's true stereo baseline, 386.1448 / 718.856 = 0.5372 m.
  EXPECT_NEAR(-calib.P[1](0, 3) / calib.P[1](0, 0), 0.5372, 1e-4);
}

}  // namespace
}  // namespace roadscale
