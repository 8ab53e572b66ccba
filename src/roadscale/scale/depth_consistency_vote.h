#pragma once

#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include <Eigen/Core>

namespace roadscale {

// Algorithm 1 of the paper: road-point candidates by segmentation, then a vote on the depth
// order of neighbouring points.

// Lines 1-5 of Alg. 1 plus the horizon: the indices of the points that lie on road pixels of
// `road_mask` (CV_8U, non-zero = road, the previous frame's; empty = no segmentation, every
// pixel passes) and, when `road_normal` is given, below the horizon: road_normal · X > 0
// (see road_plane.h). Pixels are rounded to the nearest mask cell; pixels outside the mask are not
// road. Throws Error when a non-empty mask is not CV_8U with one channel.
std::vector<int> PreselectRoadCandidates(const std::vector<Eigen::Vector2d>& pixels,
                                         const std::vector<Eigen::Vector3d>& points,
                                         const cv::Mat& road_mask,
                                         const std::optional<Eigen::Vector3d>& road_normal);

struct DepthConsistencyVoteOptions {
  // Which edges vote. Alg. 1 loops over the triangles and over each triangle's edges, so an
  // edge that two triangles share votes twice and a hull edge once (kPerTriangle, the
  // paper's reading and the default). kPerEdge lets every Delaunay edge vote once.
  enum class EdgeVisit { kPerTriangle, kPerEdge };
  EdgeVisit edge_visit = EdgeVisit::kPerTriangle;
  // beta_a: the smallest vote a point keeps. The paper gives no value. Eq. (6) cannot tell
  // which end of a breaking edge is off the road, and a point with a wrong depth can break the
  // order only with the neighbours on one side of it (above it when too far, below it when
  // too near): about half its edges. 1 keeps a point only when a strict majority of its edge
  // votes keep the depth order, so such a tie removes it.
  int min_vote = 1;

  void Check() const;
};

struct DepthConsistencyVote {
  std::vector<int> kept;   // indices of the points whose vote >= min_vote, ascending
  std::vector<int> votes;  // one per input point
  int num_triangles = 0;
};

// Lines 6-24 of Alg. 1. Every edge (i, j) of the Delaunay triangulation of `pixels` gives +1 to
// both ends when sigma = (v_i - v_j)(d_i - d_j) <= 0 (eq. 6: on a road, a point lower in the
// image is nearer) and -1 to both otherwise; d is the depth (z) of `points`. Throws Error
// when the lists differ in size.
DepthConsistencyVote VoteOnDepthConsistency(const std::vector<Eigen::Vector2d>& pixels,
                                            const std::vector<Eigen::Vector3d>& points,
                                            const DepthConsistencyVoteOptions& options);

}  // namespace roadscale
