#include "roadscale/io/kitti_calib.h"

#include <cmath>
#include <cstdio>

#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"
#include "roadscale/util/text_parsing.h"

namespace roadscale {
namespace {

// Index into KittiCalib::P for "P0".."P3", 4 for "Tr", -1 for any other key.
int KnownRow(const std::string& key) {
  if (key.size() == 2 && key[0] == 'P' && key[1] >= '0' && key[1] <= '3') return key[1] - '0';
  if (key == "Tr") return 4;
  return -1;
}

std::string FormatRow(const char* key, const KittiCalib::Matrix34d& m) {
  std::string row = key;
  row += ':';
  char buffer[32];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      std::snprintf(buffer, sizeof(buffer), " %.12e", m(r, c));
      row += buffer;
    }
  }
  return row;
}

}  // namespace

KittiCalib ReadKittiCalib(const std::string& path) {
  const std::string text = ReadInputFile(path, "KITTI calibration file");
  KittiCalib calib;
  ForEachLine(text, [&](std::string_view line, int line_number) {
    if (IsBlankOrComment(line)) return;
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos) {
      ThrowFileError(path, line_number, "expected 'KEY: numbers' (such as 'P0: ' and 12 numbers)");
    }
    const std::string key = Trim(std::string(line.substr(0, colon)));
    const int row = KnownRow(key);
    if (row < 0) return;
    const std::vector<double> v = ParseNumbers(line.substr(colon + 1), path, line_number);
    if (v.size() != 12) {
      ThrowFileError(path, line_number,
                     "expected 12 numbers (a row-major 3x4 matrix) after '" + key + ":', found " +
                         std::to_string(v.size()));
    }
    bool& seen = row < 4 ? calib.has_P[row] : calib.has_Tr;
    if (seen) ThrowFileError(path, line_number, "'" + key + ":' appears twice");
    seen = true;
    KittiCalib::Matrix34d& m = row < 4 ? calib.P[row] : calib.Tr;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) m(r, c) = v[4 * r + c];
    }
  });
  return calib;
}

PinholeCamera KittiCameraFromCalib(const KittiCalib& calib, int camera_index, int width, int height,
                                   const std::string& path) {
  if (camera_index < 0 || camera_index > 3) {
    throw Error("KITTI camera index must be 0..3, got " + std::to_string(camera_index));
  }
  const std::string key = "P" + std::to_string(camera_index);
  if (!calib.has_P[camera_index]) ThrowFileError(path, "missing row '" + key + ":'");
  const KittiCalib::Matrix34d& p = calib.P[camera_index];
  // A rectified KITTI projection is K [I | t]: no skew, and a last row (0 0 1 tz).
  const double tolerance = 1e-9 * std::abs(p(0, 0));
  if (std::abs(p(0, 1)) > tolerance || std::abs(p(1, 0)) > tolerance || p(2, 0) != 0.0 ||
      p(2, 1) != 0.0 || p(2, 2) != 1.0) {
    ThrowFileError(path, "'" + key +
                             ":' is not a rectified projection K [I | t] "
                             "(expected zero skew and a third row 0 0 1 t)");
  }
  PinholeCamera camera;
  camera.fx = p(0, 0);
  camera.fy = p(1, 1);
  camera.cx = p(0, 2);
  camera.cy = p(1, 2);
  camera.width = width;
  camera.height = height;
  try {
    camera.Check();
  } catch (const Error& e) {
    ThrowFileError(path, "'" + key + ":' " + e.what());
  }
  return camera;
}

PinholeCamera ReadKittiCamera(const std::string& path, int camera_index, int width, int height) {
  return KittiCameraFromCalib(ReadKittiCalib(path), camera_index, width, height, path);
}

void WriteKittiCalib(const std::string& path, const PinholeCamera& camera) {
  try {
    camera.Check();
  } catch (const Error& e) {
    ThrowFileError(path, std::string("refusing to write an invalid camera: ") + e.what());
  }
  KittiCalib::Matrix34d p = KittiCalib::Matrix34d::Zero();
  p.leftCols<3>() = camera.K();
  KittiCalib::Matrix34d p_right = p;
  p_right(0, 3) = -camera.fx * kKittiStereoBaseline;
  KittiCalib::Matrix34d tr;
  tr << 0.0, -1.0, 0.0, 0.0,  //
      0.0, 0.0, -1.0, 0.0,    //
      1.0, 0.0, 0.0, 0.0;

  WriteFileAtomically(path, FormatRow("P0", p) + '\n' + FormatRow("P1", p_right) + '\n' +
                                FormatRow("P2", p) + '\n' + FormatRow("P3", p_right) + '\n' +
                                FormatRow("Tr", tr) + '\n');
}

std::vector<double> ReadKittiTimes(const std::string& path) {
  const std::string text = ReadInputFile(path, "timestamps file");
  std::vector<double> times;
  ForEachLine(text, [&](std::string_view line, int line_number) {
    if (IsBlankOrComment(line)) return;
    const std::vector<double> v = ParseNumbers(line, path, line_number);
    if (v.size() != 1) {
      ThrowFileError(
          path, line_number,
          "expected one timestamp in seconds, found " + std::to_string(v.size()) + " numbers");
    }
    if (!times.empty() && v[0] <= times.back()) {
      ThrowFileError(path, line_number, "timestamps must increase");
    }
    times.push_back(v[0]);
  });
  return times;
}

}  // namespace roadscale
