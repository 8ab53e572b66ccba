#include "roadscale/synth/road_plane_file.h"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "roadscale/util/error.h"
#include "roadscale/util/text_parsing.h"

namespace roadscale::synth {

std::string FormatRoadPlaneRow(const RoadPlaneRow& row) {
  char line[160];
  std::snprintf(line, sizeof(line), "%d %.12f %.12f %.12f %.12f", row.frame, row.normal.x(),
                row.normal.y(), row.normal.z(), row.height);
  return line;
}

const char* RoadPlaneFileHeader() {
  return "# frame nx ny nz h: true road plane in the camera frame (n . X = h for road points "
         "under the car, n unit and pointing down)";
}

std::vector<RoadPlaneRow> ReadRoadPlanes(const std::string& path) {
  std::ifstream file(path);
  if (!file) ThrowFileError(path, "cannot open road plane file");
  std::vector<RoadPlaneRow> rows;
  std::string line;
  int line_number = 0;
  while (std::getline(file, line)) {
    ++line_number;
    if (IsBlankOrComment(line)) continue;
    const std::vector<double> numbers = ParseNumbers(line, path, line_number);
    if (numbers.size() != 5) {
      ThrowFileError(path, line_number, "expected 5 numbers: frame nx ny nz h");
    }
    RoadPlaneRow row;
    row.frame = static_cast<int>(numbers[0]);
    if (numbers[0] != row.frame || row.frame != static_cast<int>(rows.size())) {
      ThrowFileError(path, line_number,
                     "expected frame " + std::to_string(rows.size()) + " in this row");
    }
    row.normal = Eigen::Vector3d(numbers[1], numbers[2], numbers[3]);
    row.height = numbers[4];
    if (std::abs(row.normal.norm() - 1.0) > 1e-6) {
      ThrowFileError(path, line_number, "the normal must be a unit vector");
    }
    if (!(row.height > 0.0)) ThrowFileError(path, line_number, "the height must be positive");
    rows.push_back(row);
  }
  return rows;
}

}  // namespace roadscale::synth
