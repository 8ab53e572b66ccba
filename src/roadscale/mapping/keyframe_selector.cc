#include "roadscale/mapping/keyframe_selector.h"

#include <algorithm>

#include "roadscale/util/error.h"
#include "roadscale/util/median.h"

namespace roadscale {

void KeyframeSelectorOptions::Check() const {
  CheckOption(min_parallax_px > 0.0, "mapping.keyframe_min_parallax_px", "must be > 0");
  CheckOption(min_tracked_share >= 0.0 && min_tracked_share < 1.0,
              "mapping.keyframe_min_tracked_share", "must be in [0, 1)");
  CheckOption(max_frame_gap >= 1, "mapping.keyframe_max_frame_gap", "must be >= 1");
}

std::string KeyframeReasonName(KeyframeReason reason) {
  switch (reason) {
    case KeyframeReason::kNone:
      return "none";
    case KeyframeReason::kParallax:
      return "parallax";
    case KeyframeReason::kTrackedShare:
      return "tracked_share";
    case KeyframeReason::kFrameGap:
      return "frame_gap";
  }
  return "unknown";
}

KeyframeMotion MeasureKeyframeMotion(const Keyframe& keyframe, int frame_index,
                                     const std::vector<TrackObservation>& observations,
                                     const Eigen::Matrix3d& cur_from_keyframe_rotation,
                                     const PinholeCamera& camera) {
  KeyframeMotion motion;
  motion.frame_gap = frame_index - keyframe.frame_index;
  motion.num_observations = static_cast<int>(observations.size());
  std::vector<double> parallax;
  for (const TrackObservation& observation : observations) {
    const auto seen = keyframe.observations.find(observation.track_id);
    if (seen == keyframe.observations.end()) continue;
    const Eigen::Vector3d rotated = cur_from_keyframe_rotation * camera.Unproject(seen->second);
    if (rotated.z() <= 0.0) continue;
    parallax.push_back((camera.Project(rotated) - observation.pixel).norm());
  }
  if (!keyframe.observations.empty()) {
    motion.tracked_share =
        static_cast<double>(parallax.size()) / static_cast<double>(keyframe.observations.size());
  }
  if (!parallax.empty()) motion.parallax_px = Median(std::move(parallax));
  return motion;
}

KeyframeReason SelectKeyframe(const KeyframeMotion& motion, bool stationary,
                              const KeyframeSelectorOptions& options) {
  if (stationary || motion.num_observations == 0) return KeyframeReason::kNone;
  if (motion.parallax_px >= options.min_parallax_px) return KeyframeReason::kParallax;
  if (motion.tracked_share < options.min_tracked_share) return KeyframeReason::kTrackedShare;
  if (motion.frame_gap >= options.max_frame_gap) return KeyframeReason::kFrameGap;
  return KeyframeReason::kNone;
}

}  // namespace roadscale
