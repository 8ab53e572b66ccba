#pragma once

#include <cstdint>
#include <map>

#include <opencv2/core.hpp>

#include "roadscale/geometry/rigid3.h"

#include <Eigen/Core>

namespace roadscale {

// A frame kept in the local window: its pose, what it saw, and its road mask (for the road
// selection of the next keyframe pair).
struct Keyframe {
  int frame_index = 0;
  Rigid3d cam_from_world = Rigid3d::Identity();
  // Track id -> pixel of every track seen in this frame. Observations the bundle adjuster
  // rejects are erased.
  std::map<int64_t, Eigen::Vector2d> observations;
  cv::Mat road_mask;  // CV_8UC1, non-zero = road; empty without segmentation
  // Distance from the previous keyframe when this keyframe was created (map units): the
  // frames in between were localised at that scale, see KeyframeBackend.
  double baseline_at_creation = 0.0;
};

}  // namespace roadscale
