#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

namespace roadscale {

// The Delaunay triangles of a set of image points (OpenCV's Subdiv2D), as triples of
// indices into `pixels`, each triangle once and none of zero area. Points that
// coincide (equal after conversion to float, as Subdiv2D stores them) are one vertex: only
// the first of them appears in a triangle. Non-finite points are left out. Fewer than three
// distinct points give no triangle.
std::vector<std::array<int, 3>> DelaunayTriangles(const std::vector<Eigen::Vector2d>& pixels);

}  // namespace roadscale
