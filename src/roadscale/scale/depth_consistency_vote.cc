#include "roadscale/scale/depth_consistency_vote.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "roadscale/scale/delaunay.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

void CheckSameSize(size_t num_pixels, size_t num_points, const char* what) {
  if (num_pixels != num_points) {
    throw Error(std::string(what) + ": " + std::to_string(num_pixels) + " pixels but " +
                std::to_string(num_points) + " points; expected one point per pixel");
  }
}

}  // namespace

std::vector<int> PreselectRoadCandidates(const std::vector<Eigen::Vector2d>& pixels,
                                         const std::vector<Eigen::Vector3d>& points,
                                         const cv::Mat& road_mask,
                                         const std::optional<Eigen::Vector3d>& road_normal) {
  CheckSameSize(pixels.size(), points.size(), "road candidates");
  if (!road_mask.empty() && road_mask.type() != CV_8UC1) {
    throw Error("road mask: expected a one-channel 8-bit image (CV_8UC1), got type " +
                std::to_string(road_mask.type()));
  }
  std::vector<int> selected;
  selected.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    if (road_normal && !(road_normal->dot(points[i]) > 0.0)) continue;
    if (!road_mask.empty()) {
      const double column = std::round(pixels[i].x());
      const double row = std::round(pixels[i].y());
      if (!(column >= 0.0 && row >= 0.0 && column < road_mask.cols && row < road_mask.rows)) {
        continue;
      }
      if (road_mask.at<uint8_t>(static_cast<int>(row), static_cast<int>(column)) == 0) continue;
    }
    selected.push_back(static_cast<int>(i));
  }
  return selected;
}

void DepthConsistencyVoteOptions::Check() const {
  CheckOption(edge_visit == EdgeVisit::kPerTriangle || edge_visit == EdgeVisit::kPerEdge,
              "depth_vote.edge_visit", "must be per-triangle or per-edge");
}

DepthConsistencyVote VoteOnDepthConsistency(const std::vector<Eigen::Vector2d>& pixels,
                                            const std::vector<Eigen::Vector3d>& points,
                                            const DepthConsistencyVoteOptions& options) {
  CheckSameSize(pixels.size(), points.size(), "depth-consistency vote");
  DepthConsistencyVote result;
  result.votes.assign(points.size(), 0);
  const std::vector<std::array<int, 3>> triangles = DelaunayTriangles(pixels);
  result.num_triangles = static_cast<int>(triangles.size());

  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * triangles.size());
  for (const std::array<int, 3>& triangle : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = triangle[k];
      const int b = triangle[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  if (options.edge_visit == DepthConsistencyVoteOptions::EdgeVisit::kPerEdge) {
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  }
  for (const auto& [i, j] : edges) {
    const double sigma = (pixels[i].y() - pixels[j].y()) * (points[i].z() - points[j].z());
    const int vote = sigma <= 0.0 ? 1 : -1;
    result.votes[i] += vote;
    result.votes[j] += vote;
  }
  for (size_t i = 0; i < points.size(); ++i) {
    if (result.votes[i] >= options.min_vote) result.kept.push_back(static_cast<int>(i));
  }
  return result;
}

}  // namespace roadscale
