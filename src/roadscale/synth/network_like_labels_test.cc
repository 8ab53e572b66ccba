#include "roadscale/synth/network_like_labels.h"

#include <gtest/gtest.h>

#include "roadscale/synth/mesh.h"
#include "roadscale/util/error.h"

namespace roadscale::synth {
namespace {

// A road with one car, a 40x20 box whose left edge is at `left`.
cv::Mat Frame(int left) {
  cv::Mat labels(100, 200, CV_8UC1, cv::Scalar(label::kBuilding));
  labels.rowRange(50, 100).setTo(label::kRoad);
  labels(cv::Rect(left, 60, 40, 20)).setTo(label::kCar);
  return labels;
}

int Cars(const cv::Mat& labels) { return cv::countNonZero(labels == label::kCar); }

TEST(NetworkLikeLabels, WithoutErrorsTheLabelsAreExact) {
  NetworkLikeLabels labels(LabelErrorOptions(), 1);
  for (int left : {10, 14, 18}) {
    EXPECT_EQ(cv::countNonZero(labels.Next(Frame(left)) != Frame(left)), 0);
  }
}

TEST(NetworkLikeLabels, OutlinesShrinkAndComeLate) {
  LabelErrorOptions options;
  options.dynamic_erosion_px = 2;
  options.dynamic_lag_frames = 2;
  NetworkLikeLabels labels(options, 1);
  labels.Next(Frame(10));
  labels.Next(Frame(14));
  const cv::Mat third = labels.Next(Frame(18));
  // The car where it was two frames before (left edge 10), 2 px smaller on every side; what
  // it covers now beyond that reads as road.
  EXPECT_EQ(Cars(third), 36 * 16);
  EXPECT_EQ(third.at<uint8_t>(70, 13), label::kCar);
  EXPECT_EQ(third.at<uint8_t>(70, 54), label::kRoad);
  EXPECT_EQ(third.at<uint8_t>(40, 54), label::kBuilding);
}

TEST(NetworkLikeLabels, ObjectsFlickerOutOfSomeFrames) {
  LabelErrorOptions options;
  options.dynamic_dropout = 0.5;
  NetworkLikeLabels labels(options, 7);
  int missed = 0;
  for (int i = 0; i < 200; ++i) {
    const cv::Mat out = labels.Next(Frame(10));
    const int cars = Cars(out);
    ASSERT_TRUE(cars == 0 || cars == 40 * 20);
    if (cars == 0) {
      ++missed;
      EXPECT_EQ(out.at<uint8_t>(70, 30), label::kRoad);
    }
  }
  EXPECT_GT(missed, 70);
  EXPECT_LT(missed, 130);
  // The same seed misses the same frames.
  NetworkLikeLabels again(options, 7);
  NetworkLikeLabels same(options, 7);
  for (int i = 0; i < 20; ++i) {
    EXPECT_EQ(Cars(again.Next(Frame(10))), Cars(same.Next(Frame(10))));
  }
}

TEST(NetworkLikeLabels, OptionsAreChecked) {
  LabelErrorOptions options;
  options.dynamic_dropout = 1.5;
  EXPECT_THROW(NetworkLikeLabels(options, 1), Error);
  options = LabelErrorOptions();
  options.dynamic_lag_frames = -1;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale::synth
