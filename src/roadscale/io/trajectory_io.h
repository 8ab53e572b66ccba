#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "roadscale/geometry/rigid3.h"

namespace roadscale {

// A camera trajectory: one world_from_cam pose per frame, with timestamps in seconds when
// the source has them (TUM files, KITTI times.txt); `timestamps` is empty otherwise.
struct Trajectory {
  std::vector<double> timestamps;
  std::vector<Rigid3d> world_from_cam;

  size_t size() const { return world_from_cam.size(); }
  bool HasTimestamps() const { return !timestamps.empty(); }
};

enum class TrajectoryFormat {
  kKitti,  // 12 numbers a row: row-major 3x4 world_from_cam
  kTum,    // timestamp tx ty tz qx qy qz qw (world_from_cam)
};

// "kitti" or "tum"; throws Error otherwise.
TrajectoryFormat ParseTrajectoryFormat(const std::string& name);

// Readers tolerate blank lines and '#' comments and reject anything else malformed with
// an Error naming the file and line, including a pose that is not rigid or lies beyond
// kMaxTranslationM (CheckPoseRow, io/pose_row_check.h). The 3x3 block of KITTI rows is kept
// as written (not re-orthonormalised) so that evaluation sees exactly the file's numbers.
// The file is read once, so a pipe works.
Trajectory ReadKittiTrajectory(const std::string& path);
Trajectory ReadTumTrajectory(const std::string& path);
Trajectory ReadTrajectory(const std::string& path, TrajectoryFormat format);
// The format from the first pose row (12 numbers: KITTI, 8: TUM), then the poses.
Trajectory ReadTrajectoryOfEitherFormat(const std::string& path, TrajectoryFormat* format);

// The readers' parsers on a file's contents; `path` names it in errors.
Trajectory ParseKittiTrajectory(std::string_view text, const std::string& path);
Trajectory ParseTumTrajectory(std::string_view text, const std::string& path);
TrajectoryFormat DetectTrajectoryFormat(std::string_view text, const std::string& path);

// One line without the newline, with enough digits to read back the same doubles.
std::string FormatKittiRow(const Rigid3d& world_from_cam);
std::string FormatTumRow(double timestamp, const Rigid3d& world_from_cam);

// Writers throw Error naming the file when it cannot be written. WriteTumTrajectory needs
// timestamps.
void WriteKittiTrajectory(const std::string& path, const Trajectory& trajectory);
void WriteTumTrajectory(const std::string& path, const Trajectory& trajectory);

}  // namespace roadscale
