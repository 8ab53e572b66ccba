#pragma once

#include <Eigen/Core>

namespace roadscale {

// An undistorted pinhole camera (KITTI's rectified images). Pixel centres are at integer
// coordinates, as in OpenCV and the KITTI calibration.
struct PinholeCamera {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  int width = 0;
  int height = 0;

  Eigen::Matrix3d K() const;

  // Pixel of a point in the camera frame (z > 0 is in front of the camera).
  Eigen::Vector2d Project(const Eigen::Vector3d& point_in_cam) const;
  // The viewing ray through a pixel, scaled so that its z is 1.
  Eigen::Vector3d Unproject(const Eigen::Vector2d& pixel) const;
  bool IsInside(const Eigen::Vector2d& pixel) const;

  // Throws Error unless the focal lengths are positive and the size is set.
  void Check() const;
};

// KITTI's grey left camera (P0 of the odometry sequences 00-02) at 1241x376: the default
// camera of the synthetic scenes.
PinholeCamera KittiOdometryCamera();

}  // namespace roadscale
