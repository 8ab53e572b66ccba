#pragma once

#include <cstdint>
#include <map>
#include <optional>

#include <opencv2/core.hpp>

#include "roadscale/geometry/rigid3.h"
#include "roadscale/scale/moving_shadows.h"

#include <Eigen/Core>

namespace roadscale {

// The road plane between a keyframe and the keyframe before it, measured on the road's pixels
// (road_plane_alignment.h): its height in units of the distance between the two cameras,
// which the bundle adjustment's pair term holds at h0 (road_pair_residual.h).
struct RoadPairPlane {
  int anchor_frame = 0;  // the earlier keyframe, in whose frame the plane is
  double height_per_baseline = 0.0;
  // Measured on a road mask, or on the region ahead without segmentation.
  bool on_road_mask = true;
  // False while a pair of the region ahead disagrees with both the adjusted map and the
  // window's other pairs: no term in the adjustment, but it still votes, and it comes back
  // when enough pairs agree with it (local_bundle_adjuster.cc, ReviewRoadPairs). A pair
  // measured on a road mask is dropped instead.
  bool in_adjustment = true;
};

// A frame kept in the local window: its pose, what it saw, and its road mask (for the road
// selection of the next keyframe pair).
struct Keyframe {
  int frame_index = 0;
  double timestamp = 0.0;  // seconds; NaN when unknown
  Rigid3d cam_from_world = Rigid3d::Identity();
  // Track id -> pixel of every track seen in this frame. Observations the bundle adjuster
  // rejects are erased.
  std::map<int64_t, Eigen::Vector2d> observations;
  cv::Mat road_mask;  // CV_8UC1, non-zero = road; empty without segmentation
  cv::Mat image;      // grey CV_8UC1, for the road alignment; may be empty
  // The road less the shadows of the moving objects on it, for the road alignment's second try.
  ShadowFreeRoad shadow_free_road;
  std::optional<RoadPairPlane> road_pair;
  // Distance from the previous keyframe when this keyframe was created (map units): the
  // frames in between were localised at that scale, see KeyframeBackend.
  double baseline_at_creation = 0.0;
};

}  // namespace roadscale
