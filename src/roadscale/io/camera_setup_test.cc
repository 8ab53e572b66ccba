#include "roadscale/io/camera_setup.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/error_of.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteTextFile;

using testing::ErrorOf;

CameraSetup ExampleSetup() {
  CameraSetup setup;
  setup.camera = KittiOdometryCamera();
  setup.h0 = 1.65;
  return setup;
}

TEST(CameraSetup, WriteThenReadGivesTheSameDoubles) {
  TempDir dir;
  CameraSetup written = ExampleSetup();
  written.camera.fx = 1.0 / 3.0 * 2000.0;  // needs all 17 digits
  written.h0 = 1.7321;
  WriteCameraYaml(dir.File("camera.yaml"), written);
  const CameraSetup read = ReadCameraYaml(dir.File("camera.yaml"));
  EXPECT_EQ(read.camera.fx, written.camera.fx);
  EXPECT_EQ(read.camera.fy, written.camera.fy);
  EXPECT_EQ(read.camera.cx, written.camera.cx);
  EXPECT_EQ(read.camera.cy, written.camera.cy);
  EXPECT_EQ(read.camera.width, 1241);
  EXPECT_EQ(read.camera.height, 376);
  EXPECT_EQ(read.h0, 1.7321);
}

TEST(CameraSetup, ReadsTheCameraBlockOfAProjectConfigAndIgnoresTheRest) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("config.yaml"),
                                         "# a project config\n"
                                         "Frontend:\n"
                                         "  detector: sift\n"
                                         "  max_features: [1, 2]\n"
                                         "Camera:\n"
                                         "  name: KITTI 00-02 left grey\n"
                                         "  fx: 718.856\n"
                                         "  fy: 7.18856e+02\n"
                                         "  cx: 607.1928\n"
                                         "  cy: 185.2157\n"
                                         "  width: 1241\n"
                                         "  height: 376\n"
                                         "  h0: 1.65  # metres\n"
                                         "Scale:\n"
                                         "  window: 5\n");
  const CameraSetup setup = ReadCameraYaml(path);
  EXPECT_EQ(setup.camera.fx, 718.856);
  EXPECT_EQ(setup.camera.fy, 718.856);
  EXPECT_EQ(setup.camera.cx, 607.1928);
  EXPECT_EQ(setup.camera.cy, 185.2157);
  EXPECT_EQ(setup.h0, 1.65);
}

TEST(CameraSetup, TheShippedExampleConfigIsValid) {
  const CameraSetup setup = ReadCameraYaml(ROADSCALE_SOURCE_DIR "/config/camera_example.yaml");
  EXPECT_EQ(setup.camera.fx, 718.856);
  EXPECT_EQ(setup.camera.width, 1241);
  EXPECT_EQ(setup.h0, 1.65);
}

TEST(CameraSetup, MissingKeyNamesFileLineAndKey) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("c.yaml"),
                                         "Other: 1\n"
                                         "Camera:\n"
                                         "  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n"
                                         "  width: 640\n  height: 480\n");
  const std::string message = ErrorOf([&] { ReadCameraYaml(path); });
  // The block's mark is where its first key starts.
  EXPECT_THAT(message, HasSubstr(path + ":3:"));
  EXPECT_THAT(message, HasSubstr("missing key 'h0'"));
}

TEST(CameraSetup, InvalidValueNamesItsLine) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("c.yaml"),
                                         "Camera:\n  fx: 700\n  fy: 7oo\n  cx: 320\n  cy: 240\n"
                                         "  width: 640\n  height: 480\n  h0: 1.5\n");
  const std::string message = ErrorOf([&] { ReadCameraYaml(path); });
  EXPECT_THAT(message, HasSubstr(path + ":3:"));
  EXPECT_THAT(message, HasSubstr("Camera.fy: expected a number, found '7oo'"));
}

TEST(CameraSetup, NonIntegerSizeIsRejected) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("c.yaml"),
                                         "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n"
                                         "  width: 640.5\n  height: 480\n  h0: 1.5\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(path); }),
              HasSubstr(path + ":6: Camera.width: expected an integer, found '640.5'"));
}

TEST(CameraSetup, ImplausibleValuesAreRejectedWithTheFileName) {
  TempDir dir;
  const std::string negative_h0 =
      WriteTextFile(dir.File("h0.yaml"),
                    "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n"
                    "  width: 640\n  height: 480\n  h0: -1.5\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(negative_h0); }),
              HasSubstr(negative_h0 + ":2: Camera: invalid option camera.h0"));
  const std::string outside = WriteTextFile(dir.File("pp.yaml"),
                                            "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 2400\n"
                                            "  width: 640\n  height: 480\n  h0: 1.5\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(outside); }), HasSubstr("principal point"));
}

TEST(CameraSetup, YamlSyntaxErrorCarriesItsLine) {
  TempDir dir;
  const std::string path =
      WriteTextFile(dir.File("c.yaml"), "Camera:\n  fx: 700\n  fy: [700\n  cx: 320\n");
  const std::string message = ErrorOf([&] { ReadCameraYaml(path); });
  EXPECT_THAT(message, HasSubstr(path + ":"));
  EXPECT_THAT(message, HasSubstr("invalid YAML"));
  EXPECT_THAT(message, ::testing::ContainsRegex(":[0-9]+: invalid YAML"));
}

TEST(CameraSetup, MissingBlockOrFileIsNamed) {
  TempDir dir;
  const std::string no_block = WriteTextFile(dir.File("c.yaml"), "Frontend:\n  a: 1\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(no_block); }),
              HasSubstr(no_block + ": missing the top-level 'Camera:' block"));
  const std::string scalar_block = WriteTextFile(dir.File("s.yaml"), "Camera: 5\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(scalar_block); }),
              HasSubstr("'Camera:' must be a block"));
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(dir.File("absent.yaml")); }),
              HasSubstr(dir.File("absent.yaml") + ": cannot open camera YAML file"));
}

TEST(CameraSetup, DuplicateKeyDirectoryAndAbsurdHeightAreErrors) {
  TempDir dir;
  const std::string twice = WriteTextFile(dir.File("twice.yaml"),
                                          "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n"
                                          "  width: 640\n  height: 480\n  h0: 1.5\n  fx: 800\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(twice); }),
              HasSubstr(twice + ":9: key 'fx' appears twice in one mapping (first on line 2)"));
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(dir.path().string()); }),
              HasSubstr(dir.path().string() + ": cannot open camera YAML file: is a directory"));
  const std::string millimetres = WriteTextFile(
      dir.File("mm.yaml"),
      "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n  width: 640\n  height: 480\n"
      "  h0: 1650\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(millimetres); }),
              HasSubstr("must be in [0.05, 100] metres, got 1650"));
}

TEST(CameraSetup, LensDistortionIsReadAndWrittenBack) {
  TempDir dir;
  const std::string base =
      "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n  width: 640\n  height: 480\n"
      "  h0: 1.5\n";
  EXPECT_TRUE(ReadCameraYaml(WriteTextFile(dir.File("pinhole.yaml"), base)).distortion.empty());
  const CameraSetup five =
      ReadCameraYaml(WriteTextFile(dir.File("five.yaml"), base + "  k1: -0.28\n  p2: 0.001\n"));
  EXPECT_EQ(five.distortion, (std::vector<double>{-0.28, 0.0, 0.0, 0.001, 0.0}));
  const CameraSetup eight =
      ReadCameraYaml(WriteTextFile(dir.File("eight.yaml"), base + "  k1: 0.1\n  k6: 0.02\n"));
  EXPECT_EQ(eight.distortion, (std::vector<double>{0.1, 0, 0, 0, 0, 0, 0, 0.02}));
  WriteCameraYaml(dir.File("back.yaml"), eight);
  EXPECT_EQ(ReadCameraYaml(dir.File("back.yaml")).distortion, eight.distortion);
  EXPECT_THAT(ErrorOf([&] {
                ReadCameraYaml(WriteTextFile(dir.File("bad.yaml"), base + "  k2: strong\n"));
              }),
              HasSubstr("bad.yaml:9: Camera.k2: expected a number, found 'strong'"));
}

// A typo or a term roadscale does not model silently dropped that term (issue 30, defect 4).
TEST(CameraSetup, UnknownKeysInTheCameraBlockAreErrors) {
  TempDir dir;
  const std::string base =
      "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n  width: 640\n  height: 480\n"
      "  h0: 1.5\n";
  for (const std::string key : {"K1", "s1", "k7", "focal"}) {
    const std::string path = WriteTextFile(dir.File(key + ".yaml"), base + "  " + key + ": 0.1\n");
    EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(path); }),
                HasSubstr(path + ":9: unknown key 'Camera." + key + "' (expected fx, fy"));
  }
}

// Coefficients that pass the finiteness check but make the undistorted frames blank or folded
// (issue 30, defect 5): an error naming the file and the coefficient.
TEST(CameraSetup, UnusableDistortionNamesTheFileAndTheCoefficient) {
  TempDir dir;
  const std::string base =
      "Camera:\n  fx: 718.856\n  fy: 718.856\n  cx: 607.1928\n  cy: 185.2157\n  width: 1241\n"
      "  height: 376\n  h0: 1.65\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"  k1: 1e6\n", "camera.k1: 1e+06 leaves"},
      {"  k1: -1\n", "camera.k1: -1 folds the undistortion map"},
      {"  k2: 0.05\n  k4: -1.5\n", "camera.k4: -1.5 makes the rational model's denominator"}};
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path =
        WriteTextFile(dir.File("lens" + std::to_string(i) + ".yaml"), base + cases[i].first);
    EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(path); }),
                HasSubstr(path + ":2: Camera: invalid option " + cases[i].second));
  }
  // A strong barrel lens (the rendered drives'), a pincushion and a rational lens are fine.
  for (const std::string lens :
       {"  k1: -0.3\n  k2: 0.09\n", "  k1: 0.2\n", "  k1: 0.3\n  k4: 0.25\n  p1: 0.001\n"}) {
    EXPECT_NO_THROW(ReadCameraYaml(WriteTextFile(dir.File("good.yaml"), base + lens))) << lens;
  }
}

// "k1: 1e-320" was "expected a number" (issue 30): it is a number, a subnormal one.
TEST(CameraSetup, ATinyCoefficientIsANumber) {
  TempDir dir;
  const std::string path = WriteTextFile(
      dir.File("tiny.yaml"),
      "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n  width: 640\n  height: 480\n"
      "  h0: 1.5\n  k1: 1e-320\n");
  EXPECT_EQ(ReadCameraYaml(path).distortion.at(0), 1e-320);
  const std::string huge = WriteTextFile(
      dir.File("huge.yaml"),
      "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n  width: 640\n  height: 480\n"
      "  h0: 1.5\n  k1: 1e400\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(huge); }),
              HasSubstr("Camera.k1: expected a number, found '1e400'"));
}

// h0 1e-300 and fx 7.2e7 gave unscaled or identity trajectories (issue 30, defect 6).
TEST(CameraSetup, HeightAndFocalLengthMustBePhysical) {
  TempDir dir;
  const std::string tail = "  cx: 320\n  cy: 240\n  width: 640\n  height: 480\n";
  const std::string tiny_h0 = WriteTextFile(
      dir.File("h0.yaml"), "Camera:\n  fx: 700\n  fy: 700\n" + tail + "  h0: 1e-300\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(tiny_h0); }),
              HasSubstr(tiny_h0 + ":2: Camera: invalid option camera.h0: the camera height above "
                                  "the road must be in [0.05, 100] metres, got 1e-300"));
  const std::string long_fx = WriteTextFile(
      dir.File("fx.yaml"), "Camera:\n  fx: 7.2e7\n  fy: 700\n" + tail + "  h0: 1.5\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(long_fx); }),
              HasSubstr(long_fx + ":2: Camera: invalid option camera.fx: 7.2e+07 px over an "
                                  "image side of 640 px is no lens's focal length"));
  const std::string short_fy = WriteTextFile(
      dir.File("fy.yaml"), "Camera:\n  fx: 700\n  fy: 1e-300\n" + tail + "  h0: 1.5\n");
  EXPECT_THAT(ErrorOf([&] { ReadCameraYaml(short_fy); }), HasSubstr("invalid option camera.fy"));
}

TEST(CameraSetup, WriterRefusesAnInvalidCameraAndAnUnwritablePath) {
  TempDir dir;
  CameraSetup bad = ExampleSetup();
  bad.h0 = 0.0;
  EXPECT_THROW(WriteCameraYaml(dir.File("c.yaml"), bad), Error);
  EXPECT_THAT(ErrorOf([&] { WriteCameraYaml(dir.File("no/such/dir/c.yaml"), ExampleSetup()); }),
              HasSubstr("no/such/dir/c.yaml: cannot write"));
}

}  // namespace
}  // namespace roadscale
