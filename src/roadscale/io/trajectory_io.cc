#include "roadscale/io/trajectory_io.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "roadscale/io/pose_row_check.h"
#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"
#include "roadscale/util/text_parsing.h"

namespace roadscale {
namespace {

std::string FormatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  return buffer;
}

template <typename RowFormatter>
void WriteRows(const std::string& path, size_t count, RowFormatter format_row) {
  std::string text;
  for (size_t i = 0; i < count; ++i) text += format_row(i) + '\n';
  WriteFileAtomically(path, text);
}

}  // namespace

TrajectoryFormat ParseTrajectoryFormat(const std::string& name) {
  if (name == "kitti") return TrajectoryFormat::kKitti;
  if (name == "tum") return TrajectoryFormat::kTum;
  throw Error("unknown trajectory format '" + name + "' (expected kitti or tum)");
}

Trajectory ParseKittiTrajectory(std::string_view text, const std::string& path) {
  Trajectory trajectory;
  ForEachLine(text, [&](std::string_view line, int line_number) {
    if (IsBlankOrComment(line)) return;
    const std::vector<double> v = ParseNumbers(line, path, line_number);
    if (v.size() != 12) {
      ThrowFileError(
          path, line_number,
          "expected 12 numbers (a row-major 3x4 pose), found " + std::to_string(v.size()));
    }
    Rigid3d pose = Rigid3d::Identity();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) pose.matrix()(r, c) = v[4 * r + c];
    }
    CheckPoseRow(pose.linear(), pose.translation(), path, line_number);
    trajectory.world_from_cam.push_back(pose);
  });
  return trajectory;
}

Trajectory ParseTumTrajectory(std::string_view text, const std::string& path) {
  Trajectory trajectory;
  ForEachLine(text, [&](std::string_view line, int line_number) {
    if (IsBlankOrComment(line)) return;
    const std::vector<double> v = ParseNumbers(line, path, line_number);
    if (v.size() != 8) {
      ThrowFileError(
          path, line_number,
          "expected 8 numbers (timestamp tx ty tz qx qy qz qw), found " + std::to_string(v.size()));
    }
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    // Normalising hides a zero or garbage quaternion; a unit one written with few digits
    // is within the rotation tolerance of length 1.
    if (!(std::abs(q.norm() - 1.0) <= kRotationTolerance)) {
      ThrowFileError(
          path, line_number,
          "the quaternion (qx qy qz qw) has length " + std::to_string(q.norm()) + ", expected 1");
    }
    if (trajectory.HasTimestamps() && v[0] <= trajectory.timestamps.back()) {
      ThrowFileError(path, line_number, "timestamps must increase");
    }
    const Eigen::Matrix3d rotation = q.normalized().toRotationMatrix();
    const Eigen::Vector3d translation(v[1], v[2], v[3]);
    CheckPoseRow(rotation, translation, path, line_number);
    trajectory.timestamps.push_back(v[0]);
    trajectory.world_from_cam.push_back(MakeRigid3d(rotation, translation));
  });
  return trajectory;
}

TrajectoryFormat DetectTrajectoryFormat(std::string_view text, const std::string& path) {
  std::optional<TrajectoryFormat> format;
  ForEachLine(text, [&](std::string_view line, int line_number) {
    if (format || IsBlankOrComment(line)) return;
    const size_t count = ParseNumbers(line, path, line_number).size();
    if (count == 8) {
      format = TrajectoryFormat::kTum;
    } else if (count == 12) {
      format = TrajectoryFormat::kKitti;
    } else {
      ThrowFileError(path, line_number,
                     "cannot tell the format from a row of " + std::to_string(count) +
                         " numbers (KITTI: 12, TUM: 8); give --format kitti|tum");
    }
  });
  if (!format) ThrowFileError(path, "no poses in the file");
  return *format;
}

Trajectory ReadKittiTrajectory(const std::string& path) {
  return ParseKittiTrajectory(ReadInputFile(path, "trajectory file"), path);
}

Trajectory ReadTumTrajectory(const std::string& path) {
  return ParseTumTrajectory(ReadInputFile(path, "trajectory file"), path);
}

Trajectory ReadTrajectory(const std::string& path, TrajectoryFormat format) {
  return format == TrajectoryFormat::kKitti ? ReadKittiTrajectory(path) : ReadTumTrajectory(path);
}

Trajectory ReadTrajectoryOfEitherFormat(const std::string& path, TrajectoryFormat* format) {
  const std::string text = ReadInputFile(path, "trajectory file");
  *format = DetectTrajectoryFormat(text, path);
  return *format == TrajectoryFormat::kKitti ? ParseKittiTrajectory(text, path)
                                             : ParseTumTrajectory(text, path);
}

std::string FormatKittiRow(const Rigid3d& world_from_cam) {
  std::string row;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (!row.empty()) row += ' ';
      row += FormatNumber(world_from_cam.matrix()(r, c));
    }
  }
  return row;
}

std::string FormatTumRow(double timestamp, const Rigid3d& world_from_cam) {
  const Eigen::Quaterniond q(world_from_cam.rotation());
  const Eigen::Vector3d& t = world_from_cam.translation();
  std::string row = FormatNumber(timestamp);
  for (double value : {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()}) {
    row += ' ';
    row += FormatNumber(value);
  }
  return row;
}

void WriteKittiTrajectory(const std::string& path, const Trajectory& trajectory) {
  WriteRows(path, trajectory.size(),
            [&](size_t i) { return FormatKittiRow(trajectory.world_from_cam[i]); });
}

void WriteTumTrajectory(const std::string& path, const Trajectory& trajectory) {
  if (trajectory.timestamps.size() != trajectory.size()) {
    ThrowFileError(path, "a TUM trajectory needs one timestamp per pose");
  }
  WriteRows(path, trajectory.size(), [&](size_t i) {
    return FormatTumRow(trajectory.timestamps[i], trajectory.world_from_cam[i]);
  });
}

}  // namespace roadscale
