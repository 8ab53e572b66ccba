#include "roadscale/io/image_undistorter.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

cv::Mat CameraMatrix(const PinholeCamera& camera) {
  return (cv::Mat_<double>(3, 3) << camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0,
          1.0);
}

void CheckDistortion(const PinholeCamera& camera, const std::vector<double>& distortion) {
  camera.Check();
  CheckOption(distortion.size() == 5 || distortion.size() == 8, "distortion",
              "needs 5 (k1 k2 p1 p2 k3) or 8 (with k4 k5 k6) coefficients");
}

}  // namespace

ImageUndistorter::ImageUndistorter(const PinholeCamera& camera,
                                   const std::vector<double>& distortion) {
  CheckDistortion(camera, distortion);
  const cv::Mat K = CameraMatrix(camera);
  cv::initUndistortRectifyMap(K, cv::Mat(distortion), cv::Mat(), K,
                              cv::Size(camera.width, camera.height), CV_16SC2, map_xy_, map_frac_);
}

cv::Mat ImageUndistorter::Undistort(const cv::Mat& image) const {
  cv::Mat undistorted;
  cv::remap(image, undistorted, map_xy_, map_frac_, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
  return undistorted;
}

ImageDistorter::ImageDistorter(const PinholeCamera& camera, const std::vector<double>& distortion) {
  CheckDistortion(camera, distortion);
  // Each distorted pixel's ideal position: undistort its coordinates (iteratively, to
  // 1e-10 of a normalised unit) and project them with the same K.
  std::vector<cv::Point2f> distorted;
  distorted.reserve(static_cast<size_t>(camera.width) * static_cast<size_t>(camera.height));
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) distorted.emplace_back(u, v);
  }
  std::vector<cv::Point2f> ideal;
  const cv::Mat K = CameraMatrix(camera);
  cv::undistortPoints(distorted, ideal, K, cv::Mat(distortion), cv::Mat(), K,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-10));
  map_x_.create(camera.height, camera.width, CV_32FC1);
  map_y_.create(camera.height, camera.width, CV_32FC1);
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const cv::Point2f& p = ideal[static_cast<size_t>(v) * camera.width + u];
      map_x_.at<float>(v, u) = p.x;
      map_y_.at<float>(v, u) = p.y;
    }
  }
}

cv::Mat ImageDistorter::Distort(const cv::Mat& image, int interpolation) const {
  cv::Mat distorted;
  cv::remap(image, distorted, map_x_, map_y_, interpolation, cv::BORDER_CONSTANT);
  return distorted;
}

}  // namespace roadscale
