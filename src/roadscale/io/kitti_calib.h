#pragma once

#include <array>
#include <string>
#include <vector>

#include "roadscale/geometry/pinhole_camera.h"

#include <Eigen/Core>

namespace roadscale {

// The rows of a KITTI odometry calib.txt: the rectified projection matrices P0..P3
// (P_i = K [I | t_i], cameras 0/1 grey left/right, 2/3 colour left/right) and Tr
// (velodyne to camera 0).
struct KittiCalib {
  using Matrix34d = Eigen::Matrix<double, 3, 4, Eigen::RowMajor>;
  std::array<Matrix34d, 4> P;
  std::array<bool, 4> has_P = {false, false, false, false};
  Matrix34d Tr = Matrix34d::Zero();
  bool has_Tr = false;
};

// Reads `KEY: v1 ... v12` rows. P0..P3 and Tr must have exactly 12 numbers; other keys are
// ignored (KITTI raw calibration files carry more); blank lines and '#' comments are
// tolerated. Throws Error naming the file and line on a malformed row or a repeated key.
KittiCalib ReadKittiCalib(const std::string& path);

// The intrinsics of camera `camera_index` (0..3) from its P row, with the given image size
// (calib.txt does not hold one: take it from the first image). Throws Error naming `path`
// (used in the message only) when the row is missing or is not K [I | t] with fx, fy > 0.
PinholeCamera KittiCameraFromCalib(const KittiCalib& calib, int camera_index, int width, int height,
                                   const std::string& path);

// ReadKittiCalib + KittiCameraFromCalib.
PinholeCamera ReadKittiCamera(const std::string& path, int camera_index, int width, int height);

// KITTI's stereo baseline in metres (between cameras 0 and 1, and 2 and 3).
inline constexpr double kKittiStereoBaseline = 0.54;

// Writes a calib.txt that KITTI tools read: P0 = P2 = K [I | 0], P1 = P3 = K [I | (-b, 0, 0)]
// with b = kKittiStereoBaseline (so P(0,3) = -fx * b, as in KITTI's files), and Tr the axis
// change from a velodyne at the camera's centre (x forward, y left, z up) to the camera
// (x right, y down, z forward). Numbers are written in KITTI's %.12e format. Throws Error
// naming the file when it cannot be written or the camera fails Check().
void WriteKittiCalib(const std::string& path, const PinholeCamera& camera);

// Reads a KITTI times.txt: one timestamp in seconds a line, strictly increasing. Blank
// lines and '#' comments are tolerated; anything else throws Error naming the file and line.
std::vector<double> ReadKittiTimes(const std::string& path);

}  // namespace roadscale
