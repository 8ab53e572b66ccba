#include "roadscale/segmentation/label_iou.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(LabelIou, CountsOnlyPixelsTheGroundTruthKnows) {
  cv::Mat truth(1, 8, CV_8U, cv::Scalar(2));
  cv::Mat predicted(1, 8, CV_8U, cv::Scalar(2));
  // truth road at 0..3, prediction road at 2..5; pixel 5 is ignore in the truth.
  truth.colRange(0, 4).setTo(0);
  predicted.colRange(2, 6).setTo(0);
  truth.at<uchar>(5) = 255;
  ClassSetIou iou;
  iou.Add(predicted, truth, {0});
  EXPECT_DOUBLE_EQ(iou.intersection, 2.0);
  EXPECT_DOUBLE_EQ(iou.union_, 5.0);
  EXPECT_DOUBLE_EQ(iou.Iou(), 0.4);
  iou.Add(truth, truth, {0});
  EXPECT_DOUBLE_EQ(iou.Iou(), 6.0 / 9.0);
}

TEST(LabelIou, ClassSetsCountAsOneClass) {
  cv::Mat truth(1, 4, CV_8U, cv::Scalar(13));
  cv::Mat predicted(1, 4, CV_8U, cv::Scalar(14));
  ClassSetIou iou;
  iou.Add(predicted, truth, {13, 14});
  EXPECT_DOUBLE_EQ(iou.Iou(), 1.0);
  ClassSetIou empty;
  EXPECT_TRUE(std::isnan(empty.Iou()));
}

TEST(LabelIou, MaskIou) {
  cv::Mat a(2, 2, CV_8U, cv::Scalar(0));
  cv::Mat b(2, 2, CV_8U, cv::Scalar(0));
  EXPECT_TRUE(std::isnan(MaskIou(a, b)));
  a.at<uchar>(0, 0) = 255;
  a.at<uchar>(0, 1) = 255;
  b.at<uchar>(0, 1) = 1;
  EXPECT_DOUBLE_EQ(MaskIou(a, b), 0.5);
}

TEST(LabelIou, PooledMaskIouSumsBeforeDividing) {
  PooledMaskIou pooled;
  EXPECT_TRUE(std::isnan(pooled.Iou()));
  cv::Mat a = cv::Mat::zeros(4, 4, CV_8U), b = cv::Mat::zeros(4, 4, CV_8U);
  a(cv::Rect(0, 0, 2, 2)) = 1;  // 4 pixels, all shared: 4 / 4
  b(cv::Rect(0, 0, 2, 2)) = 255;
  pooled.Add(a, b);
  cv::Mat c = cv::Mat::zeros(4, 4, CV_8U), d = cv::Mat::zeros(4, 4, CV_8U);
  c(cv::Rect(0, 0, 4, 3)) = 1;  // 12 and 4 pixels, 4 shared: 4 / 12
  d(cv::Rect(0, 0, 4, 1)) = 1;
  pooled.Add(c, d);
  // Pooled: 8 / 16, not the mean of the two IoUs (1 and 1/3).
  EXPECT_DOUBLE_EQ(pooled.Iou(), 0.5);
  EXPECT_THROW(pooled.Add(a, cv::Mat::zeros(3, 4, CV_8U)), Error);
}

}  // namespace
}  // namespace roadscale
