#include "roadscale/io/image_undistorter.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include "roadscale/testing/frontend_test_util.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// A dash-cam-like lens on a 640x360 image: strong barrel distortion.
PinholeCamera Camera() {
  PinholeCamera camera;
  camera.fx = camera.fy = 400.0;
  camera.cx = 319.5;
  camera.cy = 179.5;
  camera.width = 640;
  camera.height = 360;
  return camera;
}
const std::vector<double> kBarrel = {-0.3, 0.09, 0.001, -0.0005, -0.01};

// Mean absolute grey difference over the image without a 20 px border.
double MeanDifference(const cv::Mat& a, const cv::Mat& b) {
  const cv::Rect inner(20, 20, a.cols - 40, a.rows - 40);
  cv::Mat difference;
  cv::absdiff(a(inner), b(inner), difference);
  return cv::mean(difference)[0];
}

TEST(ImageUndistorter, UndistortingADistortedImageGivesThePinholeImageBack) {
  const PinholeCamera camera = Camera();
  const cv::Mat ideal = testing::SyntheticTexture(camera.width, camera.height);
  const cv::Mat distorted = ImageDistorter(camera, kBarrel).Distort(ideal, cv::INTER_LINEAR);
  // The lens moves the corners by tens of pixels: the distorted image is far from the ideal.
  EXPECT_GT(MeanDifference(distorted, ideal), 8.0);
  const cv::Mat undistorted = ImageUndistorter(camera, kBarrel).Undistort(distorted);
  ASSERT_EQ(undistorted.size(), ideal.size());
  ASSERT_EQ(undistorted.type(), ideal.type());
  // Two bilinear resamplings blur a little, nothing more.
  EXPECT_LT(MeanDifference(undistorted, ideal), 1.5);
}

TEST(ImageUndistorter, DistorterMovesPixelsWhereOpenCvsModelProjectsThem) {
  // A bright dot at an ideal (pinhole) pixel appears where cv::projectPoints puts the same
  // ray through the lens.
  const PinholeCamera camera = Camera();
  cv::Mat ideal(camera.height, camera.width, CV_8UC1, cv::Scalar(0));
  const cv::Point2d dot(560.0, 300.0);
  cv::circle(ideal, dot, 3, cv::Scalar(255), cv::FILLED);
  const cv::Mat distorted = ImageDistorter(camera, kBarrel).Distort(ideal, cv::INTER_LINEAR);
  const cv::Moments moments = cv::moments(distorted);
  const cv::Point2d centroid(moments.m10 / moments.m00, moments.m01 / moments.m00);

  const std::vector<cv::Point3d> ray = {
      {(dot.x - camera.cx) / camera.fx, (dot.y - camera.cy) / camera.fy, 1.0}};
  std::vector<cv::Point2d> projected;
  const cv::Mat K =
      (cv::Mat_<double>(3, 3) << camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  cv::projectPoints(ray, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, cv::Mat(kBarrel), projected);
  EXPECT_GT(cv::norm(projected[0] - dot), 20.0);  // the lens moves this corner pixel visibly
  EXPECT_LT(cv::norm(centroid - projected[0]), 0.3);
}

TEST(ImageUndistorter, RejectsAWrongCoefficientCount) {
  EXPECT_THROW(ImageUndistorter(Camera(), {0.1, 0.2}), Error);
  EXPECT_THROW(ImageDistorter(Camera(), {}), Error);
}

}  // namespace
}  // namespace roadscale
