#pragma once

#include <string>
#include <vector>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/mapping/keyframe.h"

namespace roadscale {

struct KeyframeSelectorOptions {
  // A new keyframe once the median parallax (image motion left after removing the rotation)
  // of the tracks shared with the last keyframe reaches this many pixels: the baseline then
  // suffices to triangulate the road a few metres ahead to a few per cent, at any speed. At
  // 10 px a point 10 m ahead, seen with KLT's ~0.2 px noise, has a 2 % depth error.
  double min_parallax_px = 10.0;
  // ... or once fewer than this share of the last keyframe's tracks are still seen (a turn,
  // an occlusion): the map must be extended before it loses the frame.
  double min_tracked_share = 0.5;
  // ... or after this many frames (a car creeping in traffic still renews its map).
  int max_frame_gap = 30;

  // Throws Error naming the first invalid option.
  void Check() const;
};

enum class KeyframeReason { kNone, kParallax, kTrackedShare, kFrameGap };
// "none", "parallax", "tracked_share", "frame_gap".
std::string KeyframeReasonName(KeyframeReason reason);

// What a frame has moved since the last keyframe.
struct KeyframeMotion {
  double parallax_px = 0.0;    // median over the shared tracks
  double tracked_share = 0.0;  // shared tracks / the keyframe's observations
  int frame_gap = 0;
  int num_observations = 0;  // the frame's tracks, shared or not
};

// The motion of `frame` (its observations and rotation) since `keyframe`.
// `cur_from_keyframe_rotation`: the frame's rotation relative to the keyframe.
KeyframeMotion MeasureKeyframeMotion(const Keyframe& keyframe, int frame_index,
                                     const std::vector<TrackObservation>& observations,
                                     const Eigen::Matrix3d& cur_from_keyframe_rotation,
                                     const PinholeCamera& camera);

// Whether the frame becomes a keyframe, and why. A stationary frame never does (it adds no
// baseline), nor does a frame without tracks (a black or burnt-out image: it adds nothing to
// the map and would take a place in the window); the caller passes `stationary`.
KeyframeReason SelectKeyframe(const KeyframeMotion& motion, bool stationary,
                              const KeyframeSelectorOptions& options);

}  // namespace roadscale
