#include "roadscale/segmentation/segmentation_masks.h"

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// 60x40 of building (2) with a car (13) block, a person (11) pixel, road (0) in the bottom
// rows, and sky (10), background (19) and ignore (255) pixels that belong to no mask.
cv::Mat ExampleLabels() {
  cv::Mat labels(40, 60, CV_8U, cv::Scalar(2));
  labels(cv::Rect(20, 10, 10, 8)).setTo(13);
  labels.at<uchar>(5, 50) = 11;
  labels.rowRange(30, 40).setTo(0);
  labels.at<uchar>(2, 2) = 10;
  labels.at<uchar>(2, 3) = 19;
  labels.at<uchar>(2, 4) = 255;
  return labels;
}

TEST(SegmentationMasks, WithoutMarginsMasksAreExactlyTheClassPixels) {
  MaskOptions options;
  options.dynamic_dilation_px = 0;
  options.road_erosion_px = 0;
  const cv::Mat labels = ExampleLabels();
  const SegmentationResult result = DeriveMasks(labels, MaskClasses(), options);
  ASSERT_EQ(result.dynamic_mask.type(), CV_8UC1);
  ASSERT_EQ(result.dynamic_mask.size(), labels.size());
  EXPECT_EQ(cv::countNonZero(result.dynamic_mask), 10 * 8 + 1);
  EXPECT_EQ(result.dynamic_mask.at<uchar>(10, 20), 255);
  EXPECT_EQ(result.dynamic_mask.at<uchar>(17, 29), 255);
  EXPECT_EQ(result.dynamic_mask.at<uchar>(5, 50), 255);
  EXPECT_EQ(result.dynamic_mask.at<uchar>(9, 20), 0);
  EXPECT_EQ(cv::countNonZero(result.road_mask), 60 * 10);
  EXPECT_EQ(result.road_mask.at<uchar>(30, 0), 255);
  EXPECT_EQ(result.road_mask.at<uchar>(29, 0), 0);
  // Static is the exact complement, so sky, background and ignore pixels are static.
  EXPECT_EQ(cv::countNonZero(result.static_mask), 60 * 40 - 81);
  EXPECT_EQ(cv::countNonZero(result.static_mask & result.dynamic_mask), 0);
  EXPECT_EQ(result.static_mask.at<uchar>(2, 4), 255);
  EXPECT_EQ(result.labels.data, labels.data);
}

TEST(SegmentationMasks, DynamicMaskGrowsByTheMargin) {
  MaskOptions options;
  options.dynamic_dilation_px = 3;
  const SegmentationResult result = DeriveMasks(ExampleLabels(), MaskClasses(), options);
  // The car spans rows 10..17 and columns 20..29: 3 px out along the axes is in, 4 px is not.
  EXPECT_EQ(result.dynamic_mask.at<uchar>(13, 17), 255);
  EXPECT_EQ(result.dynamic_mask.at<uchar>(13, 16), 0);
  EXPECT_EQ(result.dynamic_mask.at<uchar>(20, 25), 255);
  EXPECT_EQ(result.dynamic_mask.at<uchar>(21, 25), 0);
  // A disc, not a square: the corner diagonal (3, 3) away is more than 3 px from the car.
  EXPECT_EQ(result.dynamic_mask.at<uchar>(7, 17), 0);
  // The single person pixel becomes a disc of radius 3: 7 px across.
  EXPECT_EQ(cv::countNonZero(result.dynamic_mask.row(5).colRange(40, 60)), 7);
  EXPECT_EQ(cv::countNonZero(result.static_mask & result.dynamic_mask), 0);
  EXPECT_EQ(cv::countNonZero(result.static_mask | result.dynamic_mask), 60 * 40);
}

TEST(SegmentationMasks, WithoutTheDynamicMaskNothingIsDynamicAndTheRoadStays) {
  cv::Mat labels(20, 30, CV_8UC1, cv::Scalar(0));
  labels(cv::Rect(10, 5, 8, 6)).setTo(13);  // a car
  MaskOptions options;
  options.use_dynamic_mask = false;
  const SegmentationResult result = DeriveMasks(labels, MaskClasses(), options);
  ASSERT_EQ(result.dynamic_mask.size(), labels.size());
  EXPECT_EQ(cv::countNonZero(result.dynamic_mask), 0);
  EXPECT_EQ(cv::countNonZero(result.static_mask), 20 * 30);
  EXPECT_EQ(cv::countNonZero(result.road_mask), 20 * 30 - 8 * 6);
}

TEST(SegmentationMasks, RoadErosionShrinksFromOtherClassesButNotFromTheImageBorder) {
  MaskOptions options;
  options.road_erosion_px = 2;
  const SegmentationResult result = DeriveMasks(ExampleLabels(), MaskClasses(), options);
  EXPECT_EQ(result.road_mask.at<uchar>(31, 30), 0);
  EXPECT_EQ(result.road_mask.at<uchar>(32, 30), 255);
  EXPECT_EQ(result.road_mask.at<uchar>(39, 0), 255);
  EXPECT_EQ(result.road_mask.at<uchar>(39, 59), 255);
  EXPECT_EQ(cv::countNonZero(result.road_mask), 60 * 8);
}

TEST(SegmentationMasks, ClassSetsComeFromTheOptions) {
  MaskClasses classes;
  classes.road_ids = {0, 1};
  classes.dynamic_ids = {13};
  MaskOptions options;
  options.dynamic_dilation_px = 0;
  cv::Mat labels = ExampleLabels();
  labels.row(29).setTo(1);
  const SegmentationResult result = DeriveMasks(labels, classes, options);
  EXPECT_EQ(cv::countNonZero(result.dynamic_mask), 80);
  EXPECT_EQ(cv::countNonZero(result.road_mask), 60 * 11);
}

TEST(SegmentationMasks, LabelsInSetIgnoresIdsOutsideTheByteRange) {
  const cv::Mat mask = LabelsInSet(ExampleLabels(), {255, 300, -1});
  EXPECT_EQ(cv::countNonZero(mask), 1);
  EXPECT_THROW(LabelsInSet(cv::Mat(4, 4, CV_16U, cv::Scalar(0)), {0}), Error);
}

TEST(SegmentationMasks, OptionsAreChecked) {
  MaskOptions options;
  options.dynamic_dilation_px = -1;
  EXPECT_THROW(options.Check(), Error);
  MaskClasses classes;
  classes.road_ids.clear();
  EXPECT_THROW(classes.Check(), Error);
  classes.road_ids = {255};
  EXPECT_THROW(classes.Check(), Error);
}

TEST(PixelOnMask, RoundsThePixelAndIsFalseOutsideTheImage) {
  cv::Mat mask(10, 20, CV_8UC1, cv::Scalar(0));
  mask.rowRange(5, 10).setTo(255);
  EXPECT_TRUE(PixelOnMask(mask, {3.0, 7.2}));
  EXPECT_TRUE(PixelOnMask(mask, {15.0, 4.6}));   // rounds to row 5
  EXPECT_FALSE(PixelOnMask(mask, {15.0, 4.4}));  // rounds to row 4
  EXPECT_FALSE(PixelOnMask(mask, {19.6, 7.0}));  // rounds to column 20, outside
  EXPECT_FALSE(PixelOnMask(mask, {-0.6, 7.0}));  // rounds to column -1, outside
  EXPECT_TRUE(PixelOnMask(mask, {-0.4, 9.4}));
}

}  // namespace
}  // namespace roadscale
