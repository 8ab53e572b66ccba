#include "roadscale/segmentation/onnx_segmenter.h"

#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include "roadscale/segmentation/make_segmenter.h"
#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using testing::SharedPath;
using testing::TempDir;
using testing::WriteTextFile;

constexpr char kSmallModel[] = "models/espnetv2/espnetv2_s2.0_city_640x192.onnx";

std::string MakeError(const std::string& yaml) {
  try {
    SegmentationOptions options;
    options.model = yaml;
    MakeSegmenter(options);
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << yaml;
  return "";
}

// A model YAML for `onnx_file` with the ESPNetv2 preprocessing and `extra` keys.
std::string WriteModelYaml(const TempDir& dir, const std::string& onnx_file,
                           const std::string& extra = "num_classes: 20\n") {
  return WriteTextFile(dir.File("model.yaml"), "backend: onnx\nfile: " + onnx_file +
                                                   "\ninput_size: [640, 192]\n"
                                                   "channel_order: rgb\n" +
                                                   extra);
}

TEST(OnnxSegmenter, GarbageModelFileIsAnErrorNamingTheFile) {
  TempDir dir;
  WriteTextFile(dir.File("garbage.onnx"), std::string(4096, '\x07') + "not a network");
  const std::string message = MakeError(WriteModelYaml(dir, "garbage.onnx"));
  EXPECT_NE(message.find(dir.File("garbage.onnx") + ": OpenCV DNN cannot load"), std::string::npos)
      << message;
  EXPECT_NE(message.find("model.yaml"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(OnnxSegmenter, EmptyOrTruncatedModelFilesAreErrors) {
  TempDir dir;
  WriteTextFile(dir.File("empty.onnx"), "");
  EXPECT_NE(MakeError(WriteModelYaml(dir, "empty.onnx")).find("missing or empty model file"),
            std::string::npos);
  ROADSCALE_REQUIRE_SHARED(kSmallModel);
  std::ifstream real(SharedPath(kSmallModel), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(real)), std::istreambuf_iterator<char>());
  WriteTextFile(dir.File("truncated.onnx"), bytes.substr(0, bytes.size() / 3));
  EXPECT_NE(MakeError(WriteModelYaml(dir, "truncated.onnx")).find("truncated.onnx: OpenCV DNN"),
            std::string::npos);
}

TEST(OnnxSegmenter, AnImageRenamedOnnxIsAnError) {
  TempDir dir;
  cv::imwrite(dir.File("picture.png"), cv::Mat(16, 16, CV_8U, cv::Scalar(3)));
  std::filesystem::rename(dir.File("picture.png"), dir.File("picture.onnx"));
  EXPECT_NE(MakeError(WriteModelYaml(dir, "picture.onnx")).find("picture.onnx: OpenCV DNN"),
            std::string::npos);
}

TEST(OnnxSegmenter, WrongNumberOfClassesIsFoundAtLoadTime) {
  ROADSCALE_REQUIRE_SHARED(kSmallModel);
  TempDir dir;
  const std::string message =
      MakeError(WriteModelYaml(dir, SharedPath(kSmallModel).string(), "num_classes: 19\n"));
  EXPECT_NE(message.find("the network's output is [1, 20, 192, 640]"), std::string::npos)
      << message;
  EXPECT_NE(message.find("expected float [1, 19, height, width]"), std::string::npos) << message;
}

TEST(OnnxSegmenter, LabelOutputLayoutIsCheckedAtLoadTime) {
  ROADSCALE_REQUIRE_SHARED(kSmallModel);
  TempDir dir;
  const std::string message = MakeError(
      WriteModelYaml(dir, SharedPath(kSmallModel).string(), "num_classes: 20\noutput: labels\n"));
  EXPECT_NE(message.find("expected [1, height, width] or [1, 1, height, width]"), std::string::npos)
      << message;
}

TEST(OnnxSegmenter, SegmentsAGreyKittiFrameAtItsOwnSize) {
  ROADSCALE_REQUIRE_SHARED(kSmallModel);
  ROADSCALE_REQUIRE_SHARED("kitti/sequences/00/image_0/000000.png");
  TempDir dir;
  const SegmentationModel model =
      ReadSegmentationModel(WriteModelYaml(dir, SharedPath(kSmallModel).string()));
  OnnxSegmenter segmenter(model, OnnxSegmenter::Options());
  const cv::Mat image = cv::imread(SharedPath("kitti/sequences/00/image_0/000000.png").string(),
                                   cv::IMREAD_UNCHANGED);
  ASSERT_EQ(image.type(), CV_8UC1);
  const SegmentationResult result = segmenter.Segment(image, "000000");
  ASSERT_EQ(result.labels.size(), image.size());
  ASSERT_EQ(result.labels.type(), CV_8UC1);
  double max_label = 0.0;
  cv::minMaxLoc(result.labels, nullptr, &max_label);
  EXPECT_LE(max_label, 19.0);
  for (const cv::Mat& mask : {result.dynamic_mask, result.static_mask, result.road_mask}) {
    EXPECT_EQ(mask.size(), image.size());
    EXPECT_EQ(mask.type(), CV_8UC1);
  }
  EXPECT_GT(cv::countNonZero(result.road_mask), image.total() / 10);
  EXPECT_GT(result.milliseconds, 0.0);
  EXPECT_TRUE(result.fresh);
  EXPECT_NE(segmenter.Description().find("640x192 input"), std::string::npos);
  // Same input, same output.
  EXPECT_EQ(cv::countNonZero(segmenter.Segment(image, "000000").labels != result.labels), 0);
  EXPECT_THROW(segmenter.Segment(cv::Mat(), "x"), Error);
  EXPECT_THROW(segmenter.Segment(cv::Mat(10, 10, CV_32F), "x"), Error);
}

TEST(NoSegmenter, GivesNoMasks) {
  SegmentationOptions options;
  options.model = "none";
  auto segmenter = MakeSegmenter(options);
  const SegmentationResult result = segmenter->Segment(cv::Mat(4, 4, CV_8U), "0");
  EXPECT_FALSE(result.HasLabels());
  EXPECT_TRUE(result.dynamic_mask.empty());
  EXPECT_TRUE(result.static_mask.empty());
  EXPECT_TRUE(result.road_mask.empty());
  EXPECT_NO_THROW(segmenter->CheckFrames({"0"}, cv::Size(4, 4)));
  TempDir dir;
  options.model = WriteTextFile(dir.File("none.yaml"), "backend: none\n");
  EXPECT_FALSE(MakeSegmenter(options)->Segment(cv::Mat(4, 4, CV_8U), "0").HasLabels());
  options.every = 0;
  EXPECT_THROW(MakeSegmenter(options), Error);
}

}  // namespace
}  // namespace roadscale
