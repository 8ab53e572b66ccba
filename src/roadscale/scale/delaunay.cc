#include "roadscale/scale/delaunay.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>

#include <opencv2/imgproc.hpp>

namespace roadscale {
namespace {

constexpr float kVirtualVertexDistance = 100.0F;

// Subdiv2D reports triangles by their corner coordinates, exactly the floats it was given:
// the bit patterns of those floats map a corner back to its point.
uint64_t FloatPairKey(const cv::Point2f& point) {
  uint32_t x_bits = 0;
  uint32_t y_bits = 0;
  std::memcpy(&x_bits, &point.x, sizeof(x_bits));
  std::memcpy(&y_bits, &point.y, sizeof(y_bits));
  return (static_cast<uint64_t>(x_bits) << 32) | y_bits;
}

}  // namespace

std::vector<std::array<int, 3>> DelaunayTriangles(const std::vector<Eigen::Vector2d>& pixels) {
  std::vector<std::array<int, 3>> triangles;
  std::unordered_map<uint64_t, int> index_of_corner;
  std::vector<cv::Point2f> corners;
  float min_x = 0.0F;
  float min_y = 0.0F;
  float max_x = 0.0F;
  float max_y = 0.0F;
  for (size_t i = 0; i < pixels.size(); ++i) {
    const cv::Point2f corner(static_cast<float>(pixels[i].x()), static_cast<float>(pixels[i].y()));
    if (!std::isfinite(corner.x) || !std::isfinite(corner.y)) continue;
    // Signed zeros differ in bits but not in position.
    const cv::Point2f key_corner(corner.x + 0.0F, corner.y + 0.0F);
    if (!index_of_corner.emplace(FloatPairKey(key_corner), static_cast<int>(i)).second) continue;
    if (corners.empty()) {
      min_x = max_x = corner.x;
      min_y = max_y = corner.y;
    }
    min_x = std::min(min_x, corner.x);
    max_x = std::max(max_x, corner.x);
    min_y = std::min(min_y, corner.y);
    max_y = std::max(max_y, corner.y);
    corners.push_back(key_corner);
  }
  if (corners.size() < 3) return triangles;

  // Subdiv2D wants an integer rectangle that strictly contains every point, and puts three
  // virtual vertices at about three times its size: so close that they steal the hull's
  // triangles (points on the hull connect to them instead of to each other). A rectangle far
  // larger than the points moves them away; the image coordinates stay exact in float.
  const float extent = std::max({max_x - min_x, max_y - min_y, 1.0F});
  const float margin = kVirtualVertexDistance * extent;
  const int left = static_cast<int>(std::floor(min_x - margin));
  const int top = static_cast<int>(std::floor(min_y - margin));
  const int right = static_cast<int>(std::ceil(max_x + margin));
  const int bottom = static_cast<int>(std::ceil(max_y + margin));
  cv::Subdiv2D subdivision(cv::Rect(left, top, right - left, bottom - top));
  subdivision.insert(corners);

  std::vector<cv::Vec6f> corner_triples;
  subdivision.getTriangleList(corner_triples);
  triangles.reserve(corner_triples.size());
  for (const cv::Vec6f& triple : corner_triples) {
    std::array<int, 3> triangle{};
    bool known_corners = true;
    for (int k = 0; k < 3 && known_corners; ++k) {
      const auto found =
          index_of_corner.find(FloatPairKey(cv::Point2f(triple[2 * k], triple[2 * k + 1])));
      known_corners = found != index_of_corner.end();
      if (known_corners) triangle[k] = found->second;
    }
    // Corners other than inserted points would be Subdiv2D's virtual outer vertices.
    if (!known_corners) continue;
    const Eigen::Vector2d a = pixels[triangle[0]];
    const Eigen::Vector2d ab = pixels[triangle[1]] - a;
    const Eigen::Vector2d ac = pixels[triangle[2]] - a;
    const double twice_area = ab.x() * ac.y() - ab.y() * ac.x();
    if (twice_area != 0.0) triangles.push_back(triangle);
  }
  return triangles;
}

}  // namespace roadscale
