#pragma once

#include <string>
#include <vector>

#include "roadscale/geometry/pinhole_camera.h"

namespace roadscale {

// What the scale stage needs to know about the camera: its intrinsics and its height above
// the road (the known distance that turns the fitted road plane into a metric scale).
struct CameraSetup {
  PinholeCamera camera;
  // Camera height above the road in metres. 1.65 is KITTI's documented mounting height.
  double h0 = 1.65;
  // The lens's distortion in OpenCV's model: k1 k2 p1 p2 k3, or k1 k2 p1 p2 k3 k4 k5 k6
  // (rational); empty for an undistorted (rectified) camera. `camera` is the pinhole camera
  // of the undistorted image: frame sources undistort every image once, on load, to the same
  // K and size (io/image_undistorter.h), so that everything after them, segmentation
  // included, sees a pinhole image.
  std::vector<double> distortion;

  // Throws Error unless the intrinsics are valid (see PinholeCamera::Check), the principal
  // point lies inside the image, the focal lengths give a field of view a lens can have
  // (CheckFocalLength), h0 is a camera height (CheckCameraHeight) and the distortion has 0, 5 or
  // 8 finite coefficients whose undistortion map is usable (CheckDistortionMap).
  void Check() const;
};

// Reads the top-level `Camera:` block of a YAML file, stella_vslam / ORB-SLAM3 style:
//
//   Camera:
//     fx: 718.856
//     fy: 718.856
//     cx: 607.1928
//     cy: 185.2157
//     width: 1241
//     height: 376
//     h0: 1.65
//     k1: -0.28            # optional: lens distortion (OpenCV's model), 0 when not given;
//     k2: 0.07             #   k4, k5, k6 select the rational model
//     p1: 0.0002
//     p2: -0.0001
//     k3: 0.0
//
// Every key but the distortion (and `name`, a label) is required (h0 too: a silently assumed
// height would silently scale every result). Other top-level blocks (`Frontend:`, `Scale:`, ...)
// are ignored, so a project config file can be passed as it is; any other key inside `Camera:`
// is an error (a typo such as K1, or a distortion term roadscale does not model, would silently
// drop it). Throws Error naming the file, the line and the missing, unknown or invalid key. The
// result has passed Check().
CameraSetup ReadCameraYaml(const std::string& path);

// Writes a file that ReadCameraYaml reads back to the same doubles. Throws Error naming the
// file when it cannot be written or when `setup` fails Check().
void WriteCameraYaml(const std::string& path, const CameraSetup& setup);

}  // namespace roadscale
