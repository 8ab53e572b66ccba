#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/geometry/pinhole_camera.h"

namespace roadscale {

// Removes a lens's distortion (OpenCV's model, CameraSetup::distortion) from whole images,
// keeping the pinhole camera's K and size, so that the rest of the system sees an ideal
// pinhole image. Images rather than feature coordinates: the segmentation network and its
// road mask need the undistorted image, and the masks, features and KLT tracks then live in
// one geometry without converting each of them. The pixel maps are computed once; each image
// costs one bilinear remap. Barrel distortion (k1 < 0, dash cams) fills the whole frame;
// pincushion leaves black corners where the lens saw nothing.
class ImageUndistorter {
 public:
  // Throws Error on a coefficient count other than 5 or 8 or an invalid camera.
  ImageUndistorter(const PinholeCamera& camera, const std::vector<double>& distortion);

  // The undistorted image (same size and type). Thread-safe.
  cv::Mat Undistort(const cv::Mat& image) const;

 private:
  cv::Mat map_xy_;    // fixed-point source positions (CV_16SC2)
  cv::Mat map_frac_;  // their interpolation weights (CV_16UC1)
};

// The opposite, for rendering what such a lens would show (synthetic sequences): the
// distorted view of an ideal pinhole image. `interpolation` is cv::INTER_LINEAR for images,
// cv::INTER_NEAREST for labels and masks.
class ImageDistorter {
 public:
  ImageDistorter(const PinholeCamera& camera, const std::vector<double>& distortion);
  cv::Mat Distort(const cv::Mat& image, int interpolation) const;

 private:
  cv::Mat map_x_;  // CV_32FC1: where each distorted pixel lies in the ideal image
  cv::Mat map_y_;
};

}  // namespace roadscale
