#include "roadscale/pipeline/segmentation_schedule.h"

#include "roadscale/mapping/keyframe.h"
#include "roadscale/util/error.h"

namespace roadscale {

SegmentationScheduleMode ParseSegmentationScheduleMode(const std::string& name) {
  if (name == "every_frame") return SegmentationScheduleMode::kEveryFrame;
  if (name == "keyframes") return SegmentationScheduleMode::kKeyframes;
  throw Error("unknown segmentation schedule '" + name + "': expected every_frame or keyframes");
}

std::string SegmentationScheduleModeName(SegmentationScheduleMode mode) {
  return mode == SegmentationScheduleMode::kEveryFrame ? "every_frame" : "keyframes";
}

void SegmentationScheduleOptions::Check() const {
  keyframes.Check();
  CheckOption(latency_frames >= 1 && latency_frames <= 30, "segmentation.latency_frames",
              "must be in 1..30 (a frame's own masks are decided after it is tracked)");
  CheckOption(min_carried_road_share >= 0.0 && min_carried_road_share <= 1.0,
              "segmentation.min_carried_road_share", "must be in 0..1");
  carry.Check();
}

SegmentationSchedule::SegmentationSchedule(const PinholeCamera& camera,
                                           const KeyframeSelectorOptions& options)
    : camera_(camera), options_(options) {
  options_.Check();
}

bool SegmentationSchedule::Decide(const FrontendFrame& frame, bool road_lost) {
  const MotionStatus status = frame.motion.status;
  if (status == MotionStatus::kOk || status == MotionStatus::kPureRotation) {
    cur_from_last_ = frame.motion.rotation * cur_from_last_;
  }
  bool segment = !started_ || road_lost;
  if (!segment) {
    Keyframe last;
    last.frame_index = last_frame_;
    last.observations = last_observations_;
    const KeyframeMotion motion =
        MeasureKeyframeMotion(last, frame.frame_index, frame.observations, cur_from_last_, camera_);
    segment = SelectKeyframe(motion, status == MotionStatus::kStationary, options_) !=
              KeyframeReason::kNone;
  }
  if (!segment) return false;
  started_ = true;
  last_frame_ = frame.frame_index;
  last_observations_.clear();
  for (const TrackObservation& observation : frame.observations) {
    last_observations_.emplace(observation.track_id, observation.pixel);
  }
  cur_from_last_ = Eigen::Matrix3d::Identity();
  return true;
}

}  // namespace roadscale
