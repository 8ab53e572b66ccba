#include "roadscale/segmentation/network_tensors.h"

#include <string>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

OnnxModelSpec Spec(int width, int height) {
  OnnxModelSpec spec;
  spec.file = "net.onnx";
  spec.input_width = width;
  spec.input_height = height;
  spec.num_classes = 3;
  return spec;
}

float At(const cv::Mat& blob, int channel, int y, int x) {
  const int index[4] = {0, channel, y, x};
  return blob.at<float>(index);
}

TEST(MakeInputBlob, PutsChannelsInTheNetworksOrder) {
  const cv::Mat bgr(2, 2, CV_8UC3, cv::Scalar(10, 20, 30));
  OnnxModelSpec spec = Spec(2, 2);
  spec.channel_order = ChannelOrder::kRgb;
  cv::Mat blob = MakeInputBlob(bgr, spec);
  ASSERT_EQ(blob.dims, 4);
  EXPECT_EQ(blob.size[1], 3);
  EXPECT_EQ(At(blob, 0, 1, 1), 30.0f);
  EXPECT_EQ(At(blob, 1, 1, 1), 20.0f);
  EXPECT_EQ(At(blob, 2, 1, 1), 10.0f);
  // The caller's image is left as it was.
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  spec.channel_order = ChannelOrder::kBgr;
  blob = MakeInputBlob(bgr, spec);
  EXPECT_EQ(At(blob, 0, 0, 0), 10.0f);
  EXPECT_EQ(At(blob, 2, 0, 0), 30.0f);
}

TEST(MakeInputBlob, ScalesThenNormalisesEachChannel) {
  OnnxModelSpec spec = Spec(2, 2);
  spec.scale = 0.5;
  spec.mean = {1.0, 2.0, 3.0};  // in the network's (RGB) order
  spec.std = {2.0, 4.0, 8.0};
  const cv::Mat blob = MakeInputBlob(cv::Mat(2, 2, CV_8UC3, cv::Scalar(10, 20, 30)), spec);
  EXPECT_FLOAT_EQ(At(blob, 0, 0, 1), (15.0f - 1.0f) / 2.0f);  // R
  EXPECT_FLOAT_EQ(At(blob, 1, 0, 1), (10.0f - 2.0f) / 4.0f);  // G
  EXPECT_FLOAT_EQ(At(blob, 2, 0, 1), (5.0f - 3.0f) / 8.0f);   // B
}

TEST(MakeInputBlob, ConvertsBetweenGreyAndColour) {
  const cv::Mat grey(2, 2, CV_8U, cv::Scalar(40));
  cv::Mat blob = MakeInputBlob(grey, Spec(2, 2));
  ASSERT_EQ(blob.size[1], 3);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(At(blob, c, 0, 0), 40.0f);

  OnnxModelSpec one_channel = Spec(2, 2);
  one_channel.input_channels = 1;
  blob = MakeInputBlob(cv::Mat(2, 2, CV_8UC3, cv::Scalar(0, 0, 255)), one_channel);
  ASSERT_EQ(blob.size[1], 1);
  EXPECT_EQ(At(blob, 0, 0, 0), 76.0f);  // 0.299 * 255, OpenCV's BGR2GRAY
}

TEST(MakeInputBlob, StretchesToTheInputSizeWithoutSwappingWidthAndHeight) {
  // 4 wide, 2 high: left half dark, right half bright; the network wants 2 wide, 1 high.
  cv::Mat image(2, 4, CV_8U, cv::Scalar(0));
  image.colRange(2, 4).setTo(200);
  const cv::Mat blob = MakeInputBlob(image, Spec(2, 1));
  ASSERT_EQ(blob.dims, 4);
  EXPECT_EQ(blob.size[2], 1);
  EXPECT_EQ(blob.size[3], 2);
  EXPECT_EQ(At(blob, 0, 0, 0), 0.0f);
  EXPECT_EQ(At(blob, 0, 0, 1), 200.0f);
}

TEST(MakeInputBlob, RejectsImagesThatAreNot8BitGreyOrBgr) {
  EXPECT_THROW(MakeInputBlob(cv::Mat(), Spec(2, 2)), Error);
  EXPECT_THROW(MakeInputBlob(cv::Mat(2, 2, CV_32F, cv::Scalar(0)), Spec(2, 2)), Error);
  EXPECT_THROW(MakeInputBlob(cv::Mat(2, 2, CV_8UC4, cv::Scalar(0)), Spec(2, 2)), Error);
}

TEST(OutputToTrainIds, ArgmaxOverClassScoresThenTrainIds) {
  OnnxModelSpec spec = Spec(2, 1);
  spec.train_ids = {0, 13, 255};
  const int shape[4] = {1, 3, 1, 2};
  cv::Mat scores(4, shape, CV_32F, cv::Scalar(0));
  // Pixel 0: class 1 wins; pixel 1: class 2 wins over class 0.
  const int p01[4] = {0, 1, 0, 0};
  const int p20[4] = {0, 0, 0, 1};
  const int p21[4] = {0, 2, 0, 1};
  scores.at<float>(p01) = 5.0f;
  scores.at<float>(p20) = 1.0f;
  scores.at<float>(p21) = 2.0f;
  const cv::Mat labels = OutputToTrainIds(scores, spec, "m.yaml");
  ASSERT_EQ(labels.type(), CV_8UC1);
  ASSERT_EQ(labels.size(), cv::Size(2, 1));
  EXPECT_EQ(labels.at<uchar>(0, 0), 13);
  EXPECT_EQ(labels.at<uchar>(0, 1), 255);
  spec.train_ids.clear();
  EXPECT_EQ(OutputToTrainIds(scores, spec, "m.yaml").at<uchar>(0, 0), 1);
}

TEST(OutputToTrainIds, LabelOutputsInEitherShape) {
  OnnxModelSpec spec = Spec(2, 2);
  spec.output = OutputLayout::kLabels;
  spec.train_ids = {5, 6, 7};
  const int shape3[3] = {1, 2, 2};
  cv::Mat labels3(3, shape3, CV_32F);
  float* values = labels3.ptr<float>();
  values[0] = 0;
  values[1] = 2;
  values[2] = 3;  // beyond the classes: ignore
  values[3] = -1;
  cv::Mat ids = OutputToTrainIds(labels3, spec, "m.yaml");
  EXPECT_EQ(ids.at<uchar>(0, 0), 5);
  EXPECT_EQ(ids.at<uchar>(0, 1), 7);
  EXPECT_EQ(ids.at<uchar>(1, 0), 255);
  EXPECT_EQ(ids.at<uchar>(1, 1), 255);
  const int shape4[4] = {1, 1, 2, 2};
  cv::Mat labels4(4, shape4, CV_32S, cv::Scalar(1));
  ids = OutputToTrainIds(labels4, spec, "m.yaml");
  EXPECT_EQ(cv::countNonZero(ids == 6), 4);
}

TEST(OutputToTrainIds, WrongShapesNameTheFileAndTheExpectedShape) {
  OnnxModelSpec spec = Spec(2, 2);
  const int shape[4] = {1, 4, 2, 2};
  const cv::Mat four_classes(4, shape, CV_32F, cv::Scalar(0));
  try {
    OutputToTrainIds(four_classes, spec, "m.yaml");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "net.onnx: the network's output is [1, 4, 2, 2], but m.yaml says output: scores "
              "with num_classes 3: expected float [1, 3, height, width]");
  }
  spec.output = OutputLayout::kLabels;
  EXPECT_THROW(OutputToTrainIds(four_classes, spec, "m.yaml"), Error);
}

}  // namespace
}  // namespace roadscale
