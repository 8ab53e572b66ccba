#include "roadscale/io/frame_source.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/io/kitti_calib.h"
#include "roadscale/testing/error_of.h"
#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteTextFile;

using testing::ErrorOf;

constexpr int kWidth = 32;
constexpr int kHeight = 24;

PinholeCamera SmallCamera() {
  PinholeCamera camera;
  camera.fx = 50.0;
  camera.fy = 51.0;
  camera.cx = 15.5;
  camera.cy = 11.5;
  camera.width = kWidth;
  camera.height = kHeight;
  return camera;
}

// Frame i is uniformly grey with value 10 * i, so a test can tell which file it got.
int FrameValue(size_t index) { return static_cast<int>(10 * index); }

void WritePng(const std::string& path, int value, int width = kWidth, int height = kHeight) {
  fs::create_directories(fs::path(path).parent_path());
  ASSERT_TRUE(cv::imwrite(path, cv::Mat(height, width, CV_8UC1, cv::Scalar(value))));
}

std::string FrameName(size_t index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06zu.png", index);
  return name;
}

std::string TimesText(size_t rows) {
  std::string text;
  for (size_t i = 0; i < rows; ++i) text += std::to_string(0.1037 * i) + "\n";
  return text;
}

// Writes <root>/sequences/07/{image_dir, calib.txt, times.txt} and <root>/poses/07.txt (pose i
// at z = i metres); a count of 0 leaves that file out. Returns the sequence folder.
std::string MakeKittiSequence(const TempDir& root, size_t images, size_t times_rows,
                              size_t pose_rows, const std::string& image_dir = "image_0") {
  const fs::path sequence = root.path() / "sequences" / "07";
  for (size_t i = 0; i < images; ++i) {
    WritePng((sequence / image_dir / FrameName(i)).string(), FrameValue(i));
  }
  fs::create_directories(sequence);
  WriteKittiCalib((sequence / "calib.txt").string(), SmallCamera());
  if (times_rows > 0) WriteTextFile((sequence / "times.txt").string(), TimesText(times_rows));
  if (pose_rows > 0) {
    Trajectory poses;
    for (size_t i = 0; i < pose_rows; ++i) {
      Rigid3d pose = Rigid3d::Identity();
      pose.translation() = Eigen::Vector3d(0.0, 0.0, static_cast<double>(i));
      poses.world_from_cam.push_back(pose);
    }
    fs::create_directories(root.path() / "poses");
    WriteKittiTrajectory((root.path() / "poses" / "07.txt").string(), poses);
  }
  return sequence.string();
}

FrameSourceOptions OptionsFor(const std::string& input) {
  FrameSourceOptions options;
  options.input = input;
  return options;
}

std::string WriteSmallCameraYaml(const TempDir& dir, int width = kWidth, int height = kHeight) {
  CameraSetup setup;
  setup.camera = SmallCamera();
  setup.camera.width = width;
  setup.camera.height = height;
  setup.h0 = 1.2;
  WriteCameraYaml(dir.File("camera.yaml"), setup);
  return dir.File("camera.yaml");
}

// ---------------------------------------------------------------------------------------

TEST(FrameRange, ParsesTheCliForms) {
  EXPECT_TRUE(ParseFrameRange("").IsAll());
  EXPECT_TRUE(ParseFrameRange(":").IsAll());
  const FrameRange both = ParseFrameRange("100:200");
  EXPECT_EQ(both.begin, 100u);
  EXPECT_EQ(both.end, 200u);
  const FrameRange open_end = ParseFrameRange("5:");
  EXPECT_EQ(open_end.begin, 5u);
  EXPECT_EQ(open_end.end, FrameRange::kToEnd);
  EXPECT_EQ(ParseFrameRange(":7").begin, 0u);
  EXPECT_EQ(ParseFrameRange(":7").end, 7u);
  EXPECT_EQ(FormatFrameRange(both), "100:200");
  EXPECT_EQ(FormatFrameRange(open_end), "5:");
}

TEST(FrameRange, RejectsMalformedAndEmptyRanges) {
  for (const char* text : {"5", "-1:3", "a:b", "3:3", "4:2", "1:2:3", "1.5:3", "+1:3"}) {
    EXPECT_THROW(ParseFrameRange(text), Error) << text;
  }
}

TEST(FrameSourceOptions, CheckRejectsBadValues) {
  FrameSourceOptions options = OptionsFor("x");
  EXPECT_NO_THROW(options.Check());
  options.kitti_camera = 4;
  EXPECT_THROW(options.Check(), Error);
  options = OptionsFor("x");
  options.h0 = -1.0;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_THROW(OptionsFor("").Check(), Error);
  EXPECT_THROW(ParseFrameSourceType("folder"), Error);
  EXPECT_EQ(ParseFrameSourceType("images"), FrameSourceType::kImageFolder);
}

// ---------------------------------------------------------------------------------------

TEST(KittiSequence, ReadsFramesInOrderWithCalibTimesAndGroundTruth) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 5, 5, 5);
  KittiSequence source(OptionsFor(sequence));
  EXPECT_EQ(source.size(), 5u);
  EXPECT_EQ(source.kitti_camera(), 0);
  EXPECT_EQ(source.camera().camera.fx, 50.0);
  EXPECT_EQ(source.camera().camera.fy, 51.0);
  EXPECT_EQ(source.camera().camera.cx, 15.5);
  EXPECT_EQ(source.camera().camera.width, kWidth);
  EXPECT_EQ(source.camera().camera.height, kHeight);
  EXPECT_EQ(source.camera().h0, 1.65);
  ASSERT_EQ(source.notes().size(), 1u);
  EXPECT_THAT(source.notes()[0], HasSubstr("using KITTI's documented h0 = 1.65 m"));

  Frame frame;
  for (size_t i = 0; i < 5; ++i) {
    ASSERT_TRUE(source.Next(&frame)) << i;
    EXPECT_EQ(frame.index, i);
    EXPECT_DOUBLE_EQ(frame.timestamp, 0.1037 * i);
    EXPECT_EQ(frame.path, (fs::path(sequence) / "image_0" / FrameName(i)).string());
    ASSERT_EQ(frame.image.type(), CV_8UC1);
    EXPECT_EQ(frame.image.at<uint8_t>(3, 4), FrameValue(i));
  }
  EXPECT_FALSE(source.Next(&frame));

  const Trajectory* truth = source.ground_truth();
  ASSERT_NE(truth, nullptr);
  ASSERT_EQ(truth->size(), 5u);
  ASSERT_EQ(truth->timestamps.size(), 5u);
  EXPECT_EQ(truth->world_from_cam[3].translation().z(), 3.0);
  EXPECT_DOUBLE_EQ(truth->timestamps[3], 0.1037 * 3);
}

TEST(KittiSequence, MoreTimesAndPosesThanImagesLoadWithANote) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 3, 10, 12);
  KittiSequence source(OptionsFor(sequence));
  EXPECT_EQ(source.size(), 3u);
  ASSERT_NE(source.ground_truth(), nullptr);
  EXPECT_EQ(source.ground_truth()->size(), 3u);
  const std::vector<std::string> notes = source.notes();
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_THAT(notes[1], HasSubstr("times.txt has 10 timestamps for 3 images: using the first 3"));
  EXPECT_THAT(notes[2], HasSubstr("07.txt has 12 poses for 3 images"));
}

TEST(KittiSequence, FrameRangeSelectsImagesTimesAndPoses) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 6, 6, 6);
  FrameSourceOptions options = OptionsFor(sequence);
  options.frames = ParseFrameRange("2:4");
  KittiSequence source(options);
  EXPECT_EQ(source.size(), 2u);
  EXPECT_THAT(source.Describe(), HasSubstr("frames 2:4 of 6"));
  Frame frame;
  ASSERT_TRUE(source.Next(&frame));
  EXPECT_EQ(frame.index, 2u);
  EXPECT_DOUBLE_EQ(frame.timestamp, 0.1037 * 2);
  EXPECT_EQ(frame.image.at<uint8_t>(0, 0), FrameValue(2));
  ASSERT_TRUE(source.Next(&frame));
  EXPECT_EQ(frame.index, 3u);
  EXPECT_FALSE(source.Next(&frame));
  ASSERT_EQ(source.ground_truth()->size(), 2u);
  EXPECT_EQ(source.ground_truth()->world_from_cam[0].translation().z(), 2.0);

  // Random access is relative to the selection and independent of Next().
  EXPECT_EQ(source.Read(1).index, 3u);
  EXPECT_THROW(source.Read(2), Error);
}

TEST(KittiSequence, RangePastTheEndIsClampedButAStartPastItIsAnError) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 4, 4, 0);
  FrameSourceOptions options = OptionsFor(sequence);
  options.frames = ParseFrameRange("1:100");
  KittiSequence clamped(options);
  EXPECT_EQ(clamped.size(), 3u);
  EXPECT_EQ(clamped.ground_truth(), nullptr);
  ASSERT_EQ(clamped.notes().size(), 2u);
  EXPECT_THAT(clamped.notes()[1], HasSubstr("reading 1:4"));

  options.frames = ParseFrameRange("4:");
  EXPECT_THAT(ErrorOf([&] { KittiSequence source(options); }), HasSubstr("has only 4 frames"));
}

TEST(KittiSequence, ColourOutputAndTheColourCamera) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 2, 2, 0, "image_2");
  FrameSourceOptions options = OptionsFor(sequence);
  options.color = true;
  options.h0 = 1.7;
  KittiSequence source(options);
  EXPECT_EQ(source.kitti_camera(), 2);  // picked because image_0/ is absent
  EXPECT_EQ(source.camera().h0, 1.7);
  Frame frame;
  ASSERT_TRUE(source.Next(&frame));
  EXPECT_EQ(frame.image.type(), CV_8UC3);

  options.kitti_camera = 0;
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(options); }),
              HasSubstr((fs::path(sequence) / "image_0").string() + ": folder not found"));
}

TEST(KittiSequence, WithoutTimesAssumesTenHertzWithANote) {
  TempDir root;
  KittiSequence source(OptionsFor(MakeKittiSequence(root, 3, 0, 0)));
  Frame frame;
  source.Next(&frame);
  source.Next(&frame);
  EXPECT_DOUBLE_EQ(frame.timestamp, 0.1);
  ASSERT_EQ(source.notes().size(), 2u);
  EXPECT_THAT(source.notes()[1], HasSubstr("assuming 10 Hz"));
}

TEST(KittiSequence, CameraHeightComesFromOptionsThenYamlThenSequenceThenKitti) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 2, 2, 0);
  CameraSetup in_sequence;
  in_sequence.camera = SmallCamera();
  in_sequence.h0 = 1.3;
  WriteCameraYaml((fs::path(sequence) / "camera.yaml").string(), in_sequence);
  FrameSourceOptions options = OptionsFor(sequence);
  {
    KittiSequence source(options);
    EXPECT_EQ(source.camera().h0, 1.3);
    EXPECT_TRUE(source.notes().empty());
  }
  // A config for another camera: its h0 wins over the sequence's file, calib.txt's
  // intrinsics stay, and a note says so.
  CameraSetup config;
  config.camera = KittiOdometryCamera();
  config.h0 = 1.4;
  WriteCameraYaml(root.File("config.yaml"), config);
  options.camera_yaml = root.File("config.yaml");
  {
    KittiSequence source(options);
    EXPECT_EQ(source.camera().h0, 1.4);
    EXPECT_EQ(source.camera().camera.fx, 50.0);
    ASSERT_EQ(source.notes().size(), 1u);
    EXPECT_THAT(source.notes()[0], HasSubstr("other intrinsics than calib.txt"));
  }
  options.h0 = 1.5;
  EXPECT_EQ(KittiSequence(options).camera().h0, 1.5);
}

TEST(KittiSequence, MissingFolderOrNoImages) {
  TempDir root;
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(root.File("nowhere"))); }),
              HasSubstr(root.File("nowhere") + ": KITTI sequence folder not found"));
  fs::create_directories(root.path() / "seq" / "image_0");
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(root.File("seq"))); }),
              HasSubstr("image_0: no images"));
}

TEST(KittiSequence, GapInTheNumberingNamesTheFirstMissingFile) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 6, 6, 0);
  fs::remove(fs::path(sequence) / "image_0" / FrameName(3));
  fs::remove(fs::path(sequence) / "image_0" / FrameName(4));
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(sequence)); }),
              HasSubstr((fs::path(sequence) / "image_0" / "000003.png").string() + ": missing"));

  TempDir no_first;
  const std::string late = MakeKittiSequence(no_first, 3, 3, 0);
  fs::remove(fs::path(late) / "image_0" / FrameName(0));
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(late)); }),
              HasSubstr("000000.png: missing"));
}

TEST(KittiSequence, WronglyNamedPngIsRejected) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 2, 2, 0);
  WritePng((fs::path(sequence) / "image_0" / "12.png").string(), 0);
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(sequence)); }),
              HasSubstr("12.png: not a KITTI frame name"));
}

TEST(KittiSequence, CalibRowWithElevenNumbersNamesFileAndLine) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 2, 2, 0);
  const std::string calib = (fs::path(sequence) / "calib.txt").string();
  WriteTextFile(calib,
                "P0: 50 0 15.5 0 0 51 11.5 0 0 0 1 0\n"
                "P1: 50 0 15.5 -27 0 51 11.5 0 0 0 1\n");
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(sequence)); }),
              HasSubstr(calib + ":2: expected 12 numbers"));
  fs::remove(calib);
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(sequence)); }),
              HasSubstr(calib + ": cannot open"));
}

TEST(KittiSequence, TimesOrPosesShorterThanTheImagesAreErrors) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 4, 3, 0);
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(sequence)); }),
              HasSubstr((fs::path(sequence) / "times.txt").string() +
                        ": has 3 timestamps but there are 4 images"));
  TempDir root2;
  const std::string sequence2 = MakeKittiSequence(root2, 4, 4, 2);
  EXPECT_THAT(ErrorOf([&] { KittiSequence s(OptionsFor(sequence2)); }),
              HasSubstr("07.txt: has 2 poses but there are 4 images"));
}

TEST(KittiSequence, CorruptPngIsReportedWhenThatFrameIsRead) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 4, 4, 0);
  const std::string corrupt = (fs::path(sequence) / "image_0" / FrameName(2)).string();
  WriteTextFile(corrupt, "\x89PNG garbage");
  KittiSequence source(OptionsFor(sequence));  // lazy: opening does not decode frame 2
  Frame frame;
  ASSERT_TRUE(source.Next(&frame));
  ASSERT_TRUE(source.Next(&frame));
  EXPECT_THAT(ErrorOf([&] { source.Next(&frame); }), HasSubstr(corrupt + ": cannot decode image"));
}

TEST(KittiSequence, FrameOfADifferentSizeIsAnError) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 3, 3, 0);
  const std::string odd = (fs::path(sequence) / "image_0" / FrameName(1)).string();
  WritePng(odd, 0, kWidth + 2, kHeight);
  KittiSequence source(OptionsFor(sequence));
  EXPECT_THAT(ErrorOf([&] { source.Read(1); }), HasSubstr(odd + ": image is 34x24 but"));
}

// ---------------------------------------------------------------------------------------

TEST(ImageFolder, SortsNamesNaturallyAndReadsJpegAndPng) {
  TempDir dir;
  const std::string folder = dir.File("frames");
  WritePng(folder + "/img10.png", 30);
  WritePng(folder + "/img9.png", 20);
  WritePng(folder + "/img1.png", 10);
  ASSERT_TRUE(cv::imwrite(folder + "/img11.JPG", cv::Mat(kHeight, kWidth, CV_8UC1, 40)));
  WriteTextFile(folder + "/notes.txt", "not an image");
  FrameSourceOptions options = OptionsFor(folder);
  options.camera_yaml = WriteSmallCameraYaml(dir);
  ImageFolder source(options);
  EXPECT_EQ(source.size(), 4u);
  EXPECT_EQ(source.camera().h0, 1.2);
  const std::vector<int> expected = {10, 20, 30, 40};
  Frame frame;
  for (size_t i = 0; i < expected.size(); ++i) {
    ASSERT_TRUE(source.Next(&frame));
    EXPECT_EQ(frame.index, i);
    EXPECT_DOUBLE_EQ(frame.timestamp, i / 10.0);
    EXPECT_NEAR(frame.image.at<uint8_t>(5, 5), expected[i], 1) << frame.path;  // JPEG: lossy
  }
  EXPECT_FALSE(source.Next(&frame));
  EXPECT_EQ(source.ground_truth(), nullptr);
  ASSERT_EQ(source.notes().size(), 1u);
  EXPECT_THAT(source.notes()[0], HasSubstr("assuming 10 Hz"));
}

TEST(ImageFolder, UsesTimesTxtAndChecksItCoversTheImages) {
  TempDir dir;
  const std::string folder = dir.File("frames");
  for (int i = 1; i <= 3; ++i) WritePng(folder + "/000" + std::to_string(i) + ".png", i);
  WriteTextFile(folder + "/times.txt", "5.0\n5.5\n6.25\n");
  FrameSourceOptions options = OptionsFor(folder);
  options.camera_yaml = WriteSmallCameraYaml(dir);
  ImageFolder source(options);
  EXPECT_DOUBLE_EQ(source.Read(2).timestamp, 6.25);
  EXPECT_TRUE(source.notes().empty());

  WriteTextFile(folder + "/times.txt", "5.0\n5.5\n");
  EXPECT_THAT(ErrorOf([&] { ImageFolder s(options); }),
              HasSubstr("times.txt: has 2 timestamps but there are 3 images"));
}

TEST(ImageFolder, GapInNumberedFramesNamesTheMissingFile) {
  TempDir dir;
  const std::string folder = dir.File("frames");
  for (int i : {1, 2, 4}) WritePng(folder + "/000" + std::to_string(i) + ".png", i);
  FrameSourceOptions options = OptionsFor(folder);
  options.camera_yaml = WriteSmallCameraYaml(dir);
  EXPECT_THAT(ErrorOf([&] { ImageFolder s(options); }), HasSubstr(folder + "/0003.png: missing"));
}

TEST(ImageFolder, ImageSizeOnlyTakesTheSizeFromTheFirstImage) {
  TempDir dir;
  const std::string folder = dir.File("frames");
  for (int i = 1; i <= 2; ++i) WritePng(folder + "/000" + std::to_string(i) + ".png", i);
  FrameSourceOptions options = OptionsFor(folder);
  EXPECT_THAT(ErrorOf([&] { ImageFolder s(options); }), HasSubstr("needs a camera YAML"));
  options.image_size_only = true;
  const ImageFolder source(options);
  EXPECT_EQ(source.camera().camera.width, kWidth);
  EXPECT_EQ(source.camera().camera.height, kHeight);
  EXPECT_EQ(source.size(), 2u);
}

TEST(ImageFolder, NeedsAMatchingCameraYaml) {
  TempDir dir;
  const std::string folder = dir.File("frames");
  WritePng(folder + "/a.png", 0);
  EXPECT_THAT(ErrorOf([&] { ImageFolder s(OptionsFor(folder)); }),
              HasSubstr(folder + ": an image folder needs a camera YAML"));
  FrameSourceOptions options = OptionsFor(folder);
  options.camera_yaml = WriteSmallCameraYaml(dir, 64, 48);
  EXPECT_THAT(
      ErrorOf([&] { ImageFolder s(options); }),
      HasSubstr(folder + "/a.png: image is 32x24 but " + options.camera_yaml + " says 64x48"));
}

TEST(ImageFolder, MissingFolderOrNoImages) {
  TempDir dir;
  FrameSourceOptions options = OptionsFor(dir.File("none"));
  options.camera_yaml = WriteSmallCameraYaml(dir);
  EXPECT_THAT(ErrorOf([&] { ImageFolder s(options); }), HasSubstr("image folder not found"));
  fs::create_directories(dir.File("empty"));
  options.input = dir.File("empty");
  EXPECT_THAT(ErrorOf([&] { ImageFolder s(options); }), HasSubstr("empty: no images"));
}

// ---------------------------------------------------------------------------------------

constexpr int kVideoFrames = 8;
constexpr double kVideoFps = 25.0;

// An MJPG .avi whose frame i is uniformly grey at 20 * i; empty when the codec is missing.
std::string WriteTestVideo(const TempDir& dir) {
  const std::string path = dir.File("clip.avi");
  cv::VideoWriter writer(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), kVideoFps,
                         cv::Size(kWidth, kHeight), /*isColor=*/true);
  if (!writer.isOpened()) return "";
  for (int i = 0; i < kVideoFrames; ++i) {
    writer.write(cv::Mat(kHeight, kWidth, CV_8UC3, cv::Scalar(20 * i, 20 * i, 20 * i)));
  }
  writer.release();
  return path;
}

TEST(VideoFile, ReadsEveryFrameWithItsTimestamp) {
  TempDir dir;
  const std::string video = WriteTestVideo(dir);
  if (video.empty()) GTEST_SKIP() << "OpenCV cannot write MJPG .avi here (no codec/backend)";
  FrameSourceOptions options = OptionsFor(video);
  options.camera_yaml = WriteSmallCameraYaml(dir);
  VideoFile source(options);
  EXPECT_EQ(source.size(), static_cast<size_t>(kVideoFrames));
  Frame frame;
  for (int i = 0; i < kVideoFrames; ++i) {
    ASSERT_TRUE(source.Next(&frame)) << i;
    EXPECT_EQ(frame.index, static_cast<size_t>(i));
    EXPECT_NEAR(frame.timestamp, i / kVideoFps, 1e-6);
    ASSERT_EQ(frame.image.type(), CV_8UC1);
    EXPECT_NEAR(frame.image.at<uint8_t>(10, 10), 20 * i, 3);  // MJPG is lossy
    EXPECT_EQ(frame.path, video + "#" + std::to_string(i));
  }
  EXPECT_FALSE(source.Next(&frame));
}

TEST(VideoFile, RangeSkipsToTheFirstSelectedFrame) {
  TempDir dir;
  const std::string video = WriteTestVideo(dir);
  if (video.empty()) GTEST_SKIP() << "OpenCV cannot write MJPG .avi here (no codec/backend)";
  FrameSourceOptions options = OptionsFor(video);
  options.camera_yaml = WriteSmallCameraYaml(dir);
  options.frames = ParseFrameRange("3:6");
  options.color = true;
  VideoFile source(options);
  EXPECT_EQ(source.size(), 3u);
  Frame frame;
  for (int i = 3; i < 6; ++i) {
    ASSERT_TRUE(source.Next(&frame));
    EXPECT_EQ(frame.index, static_cast<size_t>(i));
    EXPECT_NEAR(frame.timestamp, i / kVideoFps, 1e-6);
    ASSERT_EQ(frame.image.type(), CV_8UC3);
    EXPECT_NEAR(frame.image.at<cv::Vec3b>(10, 10)[1], 20 * i, 3);
  }
  EXPECT_FALSE(source.Next(&frame));
}

TEST(VideoFile, UnopenableVideoAndWrongSizeAreErrors) {
  TempDir dir;
  FrameSourceOptions options = OptionsFor(WriteTextFile(dir.File("broken.mp4"), "not a video"));
  options.camera_yaml = WriteSmallCameraYaml(dir);
  EXPECT_THAT(ErrorOf([&] { VideoFile v(options); }),
              HasSubstr(dir.File("broken.mp4") + ": cannot open video"));
  options.input = dir.File("absent.mp4");
  EXPECT_THAT(ErrorOf([&] { VideoFile v(options); }),
              HasSubstr("cannot open video file: no such file"));
  options.input = dir.path().string();
  EXPECT_THAT(ErrorOf([&] { VideoFile v(options); }),
              HasSubstr(dir.path().string() + ": cannot open video file: is a directory"));

  const std::string video = WriteTestVideo(dir);
  if (video.empty()) GTEST_SKIP() << "OpenCV cannot write MJPG .avi here (no codec/backend)";
  options.input = video;
  options.camera_yaml = WriteSmallCameraYaml(dir, 64, 48);
  EXPECT_THAT(ErrorOf([&] { VideoFile v(options); }), HasSubstr("video frames are 32x24 but"));
}

// ---------------------------------------------------------------------------------------

TEST(OpenFrameSource, DetectsTheInputType) {
  TempDir root;
  const std::string sequence = MakeKittiSequence(root, 2, 2, 0);
  EXPECT_EQ(DetectFrameSourceType(sequence), FrameSourceType::kKitti);
  EXPECT_EQ(DetectFrameSourceType((fs::path(sequence) / "image_0").string()),
            FrameSourceType::kImageFolder);
  EXPECT_EQ(DetectFrameSourceType((fs::path(sequence) / "calib.txt").string()),
            FrameSourceType::kVideo);
  EXPECT_THAT(ErrorOf([&] { DetectFrameSourceType(root.File("absent")); }),
              HasSubstr("absent: input not found"));

  std::unique_ptr<FrameSource> source = OpenFrameSource(OptionsFor(sequence + "/"));
  EXPECT_EQ(source->size(), 2u);
  EXPECT_THAT(source->Describe(), HasSubstr("KITTI sequence"));
  EXPECT_THAT(source->Describe(), HasSubstr("07 (image_0, frames 0:2 of 2"));

  FrameSourceOptions images = OptionsFor((fs::path(sequence) / "image_0").string());
  images.camera_yaml = WriteSmallCameraYaml(root);
  source = OpenFrameSource(images);
  EXPECT_THAT(source->Describe(), HasSubstr("image folder"));
  Frame frame;
  ASSERT_TRUE(source->Next(&frame));
  EXPECT_EQ(frame.image.at<uint8_t>(0, 0), FrameValue(0));
}

// ---------------------------------------------------------------------------------------

// The shared copy of sequence 00 holds 200 images but the full sequence's 4,541 timestamps
// and poses: it must load, pairing the first 200 rows with the images.
TEST(KittiSequenceData, SharedSequence00LoadsWithItsFirst200Poses) {
  ROADSCALE_REQUIRE_SHARED("kitti/sequences/00");
  ROADSCALE_REQUIRE_SHARED("kitti/poses/00.txt");
  KittiSequence source(OptionsFor(testing::SharedPath("kitti/sequences/00").string()));
  EXPECT_EQ(source.size(), 200u);
  EXPECT_EQ(source.camera().camera.fx, 718.856);
  EXPECT_EQ(source.camera().camera.cx, 607.1928);
  EXPECT_EQ(source.camera().camera.width, 1241);
  EXPECT_EQ(source.camera().camera.height, 376);

  const Trajectory* truth = source.ground_truth();
  ASSERT_NE(truth, nullptr);
  ASSERT_EQ(truth->size(), 200u);
  EXPECT_TRUE(truth->world_from_cam[0].isApprox(Rigid3d::Identity(), 1e-5));
  EXPECT_EQ(truth->timestamps[1], 0.1037359);
  // 144.9 m of driving over the 200 frames (shared/README.md).
  double path_length = 0.0;
  for (size_t i = 1; i < truth->size(); ++i) {
    path_length +=
        (truth->world_from_cam[i].translation() - truth->world_from_cam[i - 1].translation())
            .norm();
  }
  EXPECT_NEAR(path_length, 144.9, 0.1);

  const std::vector<std::string> notes = source.notes();
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_THAT(notes[0], HasSubstr("h0 = 1.65 m"));
  EXPECT_THAT(notes[1], HasSubstr("4541 timestamps for 200 images"));
  EXPECT_THAT(notes[2], HasSubstr("4541 poses for 200 images"));

  // Every frame decodes at the camera's size; frames are not kept, so memory stays at one
  // image (measured in docs/benchmark-history.md).
  Frame frame;
  size_t count = 0;
  while (source.Next(&frame)) {
    ASSERT_EQ(frame.index, count);
    ASSERT_EQ(frame.image.cols, 1241);
    ASSERT_EQ(frame.image.rows, 376);
    ++count;
  }
  EXPECT_EQ(count, 200u);
}

}  // namespace
}  // namespace roadscale
