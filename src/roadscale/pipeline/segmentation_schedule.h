#pragma once

#include <map>
#include <string>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/mapping/keyframe_selector.h"
#include "roadscale/segmentation/mask_carrying.h"

namespace roadscale {

// Which frames the network sees. every_frame: all (the paper); keyframes: the frames the
// keyframe rule picks from the frontend's tracks, the others get masks carried from the last
// segmented frame (docs/benchmark-history.md, "Segmenting keyframes only").
enum class SegmentationScheduleMode { kEveryFrame, kKeyframes };
// "every_frame" | "keyframes"; throws Error naming the accepted values otherwise.
SegmentationScheduleMode ParseSegmentationScheduleMode(const std::string& name);
std::string SegmentationScheduleModeName(SegmentationScheduleMode mode);

struct SegmentationScheduleOptions {
  SegmentationScheduleMode mode = SegmentationScheduleMode::kKeyframes;
  // keyframes: the keyframe rule (KeyframeSelectorOptions) applied to the frontend's tracks
  // and rotations, in either mapping mode, with its own thresholds: a frame is segmented at
  // 30 px median parallax since the last segmented one (rotation removed), or when fewer than
  // 30 % of its tracks are still seen, or after 30 frames; a stationary frame never is (the
  // frame gap too at a stop lost the rendered jams' lengths: 1.0227 -> 1.0781 and 0.9833 ->
  // 0.9302). The back end's keyframe thresholds
  // (10 px, 50 %) would segment 62 % of KITTI 00's frames; these segment 23 % at the same
  // accuracy (docs/benchmark-history.md, "Segmenting keyframes only").
  KeyframeSelectorOptions keyframes{30.0, 0.3, 30};
  // A segmented frame's masks reach the frontend this many frames later (the frames between
  // use the older masks, carried): the network runs beside the frontend instead of holding it
  // up. Fixed, so that the output never depends on thread timing.
  int latency_frames = 3;
  // keyframes: a frame is segmented too when its carried road mask, less its carried moving
  // objects, holds less than this share of the road the network saw in the frame it was
  // carried from (0: never), unless a segmented frame is still on its way. In a jam the car
  // moves too little for the parallax rule while the cars ahead move on: the road they uncover
  // never enters the carried mask, and on rendered traffic_jam 2 the road fell to 30 % in 22
  // frames. In a turn the road swings out of it sideways: KITTI 07's second turn was 11-15 %
  // short with carried masks and within 1.4 % with every frame segmented. Half the road lost
  // is the rule: 07/160 0.9646 -> 0.9804 in length (every frame: 0.9808), ATE 0.95 -> 0.67 m;
  // KITTI 00, the rendered urban drive and highway unchanged or within noise; the rendered
  // jams as many targets missed, two rows much nearer (docs/benchmark-history.md, "A step that
  // predicts the next, and fresh masks where the carried road runs out").
  double min_carried_road_share = 0.5;
  MaskCarryOptions carry;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// Decides after the frontend has processed a frame whether the network segments it: the first
// frame, then each frame the keyframe rule picks relative to the last segmented one, and each
// frame whose road could not be carried. Frames must come in order.
class SegmentationSchedule {
 public:
  SegmentationSchedule(const PinholeCamera& camera, const KeyframeSelectorOptions& options);

  // `road_lost`: the road could not be carried into this frame (its motion not measured, or
  // too little of it left): segment it whatever the keyframe rule says.
  bool Decide(const FrontendFrame& frame, bool road_lost);

 private:
  PinholeCamera camera_;
  KeyframeSelectorOptions options_;
  bool started_ = false;
  int last_frame_ = 0;
  std::map<int64_t, Eigen::Vector2d> last_observations_;
  // The rotation from the last segmented frame to the current one (the frontend's, chained).
  Eigen::Matrix3d cur_from_last_ = Eigen::Matrix3d::Identity();
};

}  // namespace roadscale
