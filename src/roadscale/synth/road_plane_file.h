#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace roadscale::synth {

// One row of a synthetic sequence's road_planes.txt: the true road plane of a frame in its
// camera frame, n . X = height for road points near the car, n unit and pointing down.
struct RoadPlaneRow {
  int frame = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double height = 0.0;
};

// "frame nx ny nz h" with 12 decimals, without the newline.
std::string FormatRoadPlaneRow(const RoadPlaneRow& row);

// The comment line that heads the file.
const char* RoadPlaneFileHeader();

// Reads road_planes.txt: '#' comments and blank lines are skipped; every other line must
// hold an integer frame and four numbers, with frames 0, 1, 2, ... in order, a unit normal
// (to 1e-6) and a positive height. Throws Error naming the file and line otherwise.
std::vector<RoadPlaneRow> ReadRoadPlanes(const std::string& path);

}  // namespace roadscale::synth
