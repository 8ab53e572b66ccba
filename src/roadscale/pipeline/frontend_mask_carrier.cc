#include "roadscale/pipeline/frontend_mask_carrier.h"

#include "roadscale/scale/road_plane.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

int CountRoad(const SegmentationResult& result) {
  return result.road_mask.empty() ? 0 : cv::countNonZero(result.road_mask);
}

cv::Mat StaticMaskOf(const cv::Mat& dynamic_mask) {
  if (dynamic_mask.empty()) return cv::Mat();
  cv::Mat out;
  cv::bitwise_not(dynamic_mask, out);
  return out;
}

}  // namespace

FrontendMaskCarrier::FrontendMaskCarrier(const MaskCarryOptions& options, int latency_frames,
                                         const Eigen::Matrix3d& intrinsics)
    : options_(options), latency_frames_(latency_frames), intrinsics_(intrinsics) {
  options_.Check();
  CheckOption(latency_frames_ >= 1, "segmentation.latency_frames", "must be >= 1");
}

FrontendMasks FrontendMaskCarrier::Masks(int frame_index,
                                         const std::vector<Correspondence>& correspondences,
                                         const TakeFresh& take_fresh) {
  if (anchor_frame_ < 0) {
    // The first frame waits for its own masks: nothing to carry them from.
    anchor_ = take_fresh(frame_index);
    anchor_frame_ = frame_index;
    anchor_road_px_ = CountRoad(anchor_);
    road_ = anchor_.road_mask;
    dynamic_ = anchor_.dynamic_mask;
    FrontendMasks masks{anchor_.static_mask, anchor_.dynamic_mask};
    masks.road_mask = road_;
    return masks;
  }

  std::vector<Eigen::Vector2d> prev, cur;
  prev.reserve(correspondences.size());
  cur.reserve(correspondences.size());
  for (const Correspondence& c : correspondences) {
    prev.push_back(c.prev);
    cur.push_back(c.cur);
  }
  const std::optional<Eigen::Matrix3d> step = FitRoadStep(prev, cur);
  carry_failed_ = !step.has_value();
  // Without a measurement the road is taken to move as in the frame before.
  if (step) last_step_ = *step;
  steps_.emplace_back(frame_index, last_step_);

  int due = -1;
  while (!pending_.empty() && pending_.front() + latency_frames_ <= frame_index) {
    if (due >= 0) take_fresh(due);  // superseded by a newer due frame: read and dropped
    due = pending_.front();
    pending_.pop_front();
  }
  if (due >= 0) {
    anchor_ = take_fresh(due);
    anchor_frame_ = due;
    anchor_road_px_ = CountRoad(anchor_);
    cur_from_anchor_.setIdentity();
    for (const auto& [frame, cur_from_prev] : steps_) {
      if (frame > due) cur_from_anchor_ = cur_from_prev * cur_from_anchor_;
    }
  } else {
    cur_from_anchor_ = last_step_ * cur_from_anchor_;
  }
  // Keep the steps a pending frame will need when it falls due.
  const int oldest_needed = pending_.empty() ? frame_index : pending_.front();
  while (!steps_.empty() && steps_.front().first <= oldest_needed) steps_.pop_front();

  road_ = CarryRoadMask(anchor_.road_mask, cur_from_anchor_);
  dynamic_ = CarryDynamicMask(anchor_.dynamic_mask, cur_from_anchor_, frame_index - anchor_frame_,
                              options_);
  MeasureCarriedRoadShare();
  FrontendMasks masks{StaticMaskOf(dynamic_), dynamic_};
  masks.road_mask = road_;
  if (due >= 0) {
    masks.segmented_frame = due;
    masks.segmented_dynamic_mask = anchor_.dynamic_mask;
  }
  return masks;
}

void FrontendMaskCarrier::AddMotion(const TwoViewMotion& motion) {
  switch (motion.status) {
    case MotionStatus::kOk:
      predicted_rotation_ = motion.rotation;
      predicted_direction_ = motion.direction;
      break;
    case MotionStatus::kStationary:
    case MotionStatus::kPureRotation:
      predicted_rotation_ = motion.rotation;
      break;
    default:
      break;
  }
}

std::optional<Eigen::Matrix3d> FrontendMaskCarrier::FitRoadStep(
    const std::vector<Eigen::Vector2d>& prev, const std::vector<Eigen::Vector2d>& cur) const {
  if (options_.road_on_motion && predicted_direction_) {
    const std::optional<Eigen::Vector3d> normal = RoadNormalFromMotion(
        MakeRigid3d(predicted_rotation_, -predicted_rotation_ * *predicted_direction_));
    if (normal) {
      return FitRoadHomographyOnMotion(prev, cur, road_, intrinsics_, predicted_rotation_,
                                       *predicted_direction_, *normal, options_);
    }
  }
  return FitRoadHomography(prev, cur, road_, options_);
}

void FrontendMaskCarrier::MeasureCarriedRoadShare() {
  if (anchor_road_px_ == 0 || road_.empty()) {
    carried_road_share_ = 1.0;
    return;
  }
  // The road the scale stage gets: the carried road less the carried cars.
  cv::Mat free_road;
  if (dynamic_.empty()) {
    free_road = road_;
  } else {
    cv::subtract(road_, dynamic_, free_road);
  }
  carried_road_share_ = static_cast<double>(cv::countNonZero(free_road)) / anchor_road_px_;
}

}  // namespace roadscale
