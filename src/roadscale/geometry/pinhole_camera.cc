#include "roadscale/geometry/pinhole_camera.h"

#include <cmath>

#include "roadscale/util/error.h"

namespace roadscale {

Eigen::Matrix3d PinholeCamera::K() const {
  Eigen::Matrix3d k;
  k << fx, 0.0, cx, 0.0, fy, cy, 0.0, 0.0, 1.0;
  return k;
}

Eigen::Vector2d PinholeCamera::Project(const Eigen::Vector3d& point_in_cam) const {
  return {fx * point_in_cam.x() / point_in_cam.z() + cx,
          fy * point_in_cam.y() / point_in_cam.z() + cy};
}

Eigen::Vector3d PinholeCamera::Unproject(const Eigen::Vector2d& pixel) const {
  return {(pixel.x() - cx) / fx, (pixel.y() - cy) / fy, 1.0};
}

bool PinholeCamera::IsInside(const Eigen::Vector2d& pixel) const {
  return pixel.x() >= -0.5 && pixel.y() >= -0.5 && pixel.x() < width - 0.5 &&
         pixel.y() < height - 0.5;
}

void PinholeCamera::Check() const {
  CheckOption(std::isfinite(fx) && fx > 0.0, "camera.fx", "must be a positive number");
  CheckOption(std::isfinite(fy) && fy > 0.0, "camera.fy", "must be a positive number");
  CheckOption(std::isfinite(cx) && std::isfinite(cy), "camera.cx/cy", "must be finite");
  CheckOption(width > 0 && height > 0, "camera.width/height", "must be positive");
}

PinholeCamera KittiOdometryCamera() {
  PinholeCamera camera;
  camera.fx = 718.856;
  camera.fy = 718.856;
  camera.cx = 607.1928;
  camera.cy = 185.2157;
  camera.width = 1241;
  camera.height = 376;
  return camera;
}

}  // namespace roadscale
