#include "roadscale/segmentation/cityscapes.h"

#include <gtest/gtest.h>

namespace roadscale {
namespace {

TEST(Cityscapes, LabelIdsMapToTrainIds) {
  const cv::Mat table = CityscapesLabelIdToTrainIdTable();
  EXPECT_EQ(table.at<uchar>(7), 0);     // road
  EXPECT_EQ(table.at<uchar>(8), 1);     // sidewalk
  EXPECT_EQ(table.at<uchar>(23), 10);   // sky
  EXPECT_EQ(table.at<uchar>(24), 11);   // person
  EXPECT_EQ(table.at<uchar>(26), 13);   // car
  EXPECT_EQ(table.at<uchar>(31), 16);   // train
  EXPECT_EQ(table.at<uchar>(33), 18);   // bicycle
  EXPECT_EQ(table.at<uchar>(0), 255);   // unlabeled
  EXPECT_EQ(table.at<uchar>(9), 255);   // parking
  EXPECT_EQ(table.at<uchar>(29), 255);  // caravan
  EXPECT_EQ(table.at<uchar>(34), 255);
  EXPECT_EQ(CityscapesDynamicTrainIds(), (std::vector<int>{11, 12, 13, 14, 15, 16, 17, 18}));
  EXPECT_EQ(CityscapesTrainIdName(13), "car");
  EXPECT_EQ(CityscapesTrainIdName(255), "ignore");
}

TEST(Cityscapes, OverlayBlendsThePaletteAndLeavesIgnorePixels) {
  cv::Mat labels(1, 3, CV_8U);
  labels.at<uchar>(0) = 0;
  labels.at<uchar>(1) = 13;
  labels.at<uchar>(2) = 255;
  EXPECT_EQ(CityscapesTrainIdColour(0), cv::Vec3b(128, 64, 128));
  EXPECT_EQ(CityscapesTrainIdColour(13), cv::Vec3b(142, 0, 0));  // BGR of car (0, 0, 142)
  const cv::Mat grey(1, 3, CV_8U, cv::Scalar(100));
  const cv::Mat overlay = OverlayTrainIds(grey, labels, 0.5);
  ASSERT_EQ(overlay.type(), CV_8UC3);
  EXPECT_EQ(overlay.at<cv::Vec3b>(0), cv::Vec3b(114, 82, 114));
  EXPECT_EQ(overlay.at<cv::Vec3b>(1), cv::Vec3b(121, 50, 50));
  EXPECT_EQ(overlay.at<cv::Vec3b>(2), cv::Vec3b(100, 100, 100));
}

}  // namespace
}  // namespace roadscale
