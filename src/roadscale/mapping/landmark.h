#pragma once

#include <Eigen/Core>

namespace roadscale {

// A track triangulated from several keyframes of the window.
struct Landmark {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world frame
  // Road landmarks were chosen by the paper's selection (road mask, Alg. 1, Alg. 2, RANSAC)
  // on a keyframe pair. Their height under the earlier keyframe of that pair (the anchor),
  // measured along the road normal that the pair's plane fit found there, is h0.
  bool is_road = false;
  int road_anchor_frame = -1;
  Eigen::Vector3d road_normal_in_anchor = Eigen::Vector3d::UnitY();
};

}  // namespace roadscale
