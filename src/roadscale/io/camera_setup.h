#pragma once

#include <string>

#include "roadscale/geometry/pinhole_camera.h"

namespace roadscale {

// What the scale stage needs to know about the camera: its intrinsics and its height above
// the road (the known distance that turns the fitted road plane into a metric scale).
struct CameraSetup {
  PinholeCamera camera;
  // Camera height above the road in metres. 1.65 is KITTI's documented mounting height.
  double h0 = 1.65;

  // Throws Error unless the intrinsics are valid (see PinholeCamera::Check), the principal
  // point lies inside the image and h0 is a positive number.
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
//
// Every key is required (h0 too: a silently assumed height would silently scale every
// result). Other top-level blocks (`Frontend:`, `Scale:`, ...) and other keys inside
// `Camera:` are ignored, so a project config file can be passed as it is. Throws Error
// naming the file, the line and the missing or invalid key. The result has passed Check().
CameraSetup ReadCameraYaml(const std::string& path);

// Writes a file that ReadCameraYaml reads back to the same doubles. Throws Error naming the
// file when it cannot be written or when `setup` fails Check().
void WriteCameraYaml(const std::string& path, const CameraSetup& setup);

}  // namespace roadscale
