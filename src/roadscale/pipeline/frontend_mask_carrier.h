#pragma once

#include <deque>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/segmentation/mask_carrying.h"
#include "roadscale/segmentation/segmentation_result.h"

#include <Eigen/Core>

namespace roadscale {

// The frontend's masks when only some frames are segmented: each frame's moving-object mask
// (and the road mask that picks the road tracks) carried from the newest segmented frame
// whose result is due, `latency_frames` after it, through the road homographies measured
// frame by frame from the tracks. Frames must come in order.
class FrontendMaskCarrier {
 public:
  using TakeFresh = std::function<SegmentationResult(int frame_index)>;

  // `intrinsics`: the camera's K, for the road's homography on the motion
  // (MaskCarryOptions::road_on_motion).
  FrontendMaskCarrier(const MaskCarryOptions& options, int latency_frames,
                      const Eigen::Matrix3d& intrinsics);

  // The masks of `frame_index` once its tracks are followed into it (a FrontendMaskProvider's
  // work). `take_fresh` waits for a segmented frame's result: the first frame's, and each
  // segmented frame's when it falls due.
  FrontendMasks Masks(int frame_index, const std::vector<Correspondence>& correspondences,
                      const TakeFresh& take_fresh);

  // The schedule picked `frame_index` (the frame just tracked) for the network.
  void AddSegmented(int frame_index) { pending_.push_back(frame_index); }

  // The motion the frontend measured into the frame just tracked: the prediction of the next
  // frame's, on which its road homography is fitted (MaskCarryOptions::road_on_motion).
  void AddMotion(const TwoViewMotion& motion);

  // The last frame's road homography cur_from_prev (the previous one's when it could not be
  // measured, identity in the first frame), and whether it could not.
  const Eigen::Matrix3d& last_step() const { return last_step_; }
  bool carry_failed() const { return carry_failed_; }
  // The last frame's carried road less its carried moving objects, in pixels, against the
  // road of the segmented frame it was carried from (1 when that frame had none), and whether
  // a segmented frame is not yet due.
  double carried_road_share() const { return carried_road_share_; }
  bool segmentation_pending() const { return !pending_.empty(); }
  // The last frame's carried moving-object mask (empty before the first segmented frame).
  const cv::Mat& last_dynamic_mask() const { return dynamic_; }

 private:
  void MeasureCarriedRoadShare();
  // The road's homography from the last frame to this one, fitted to the tracks `prev` ->
  // `cur` on the carried road mask.
  std::optional<Eigen::Matrix3d> FitRoadStep(const std::vector<Eigen::Vector2d>& prev,
                                             const std::vector<Eigen::Vector2d>& cur) const;

  MaskCarryOptions options_;
  int latency_frames_;
  std::deque<int> pending_;  // segmented frames whose results are not yet due
  SegmentationResult anchor_;
  int anchor_frame_ = -1;
  int anchor_road_px_ = 0;
  Eigen::Matrix3d cur_from_anchor_ = Eigen::Matrix3d::Identity();
  // (frame, its road homography from the frame before), back to the oldest pending frame.
  std::deque<std::pair<int, Eigen::Matrix3d>> steps_;
  cv::Mat road_;     // this carrier's road mask of the last frame
  cv::Mat dynamic_;  // and its moving-object mask
  Eigen::Matrix3d last_step_ = Eigen::Matrix3d::Identity();
  bool carry_failed_ = false;
  double carried_road_share_ = 1.0;
  Eigen::Matrix3d intrinsics_;
  // The last rotation measured and the last direction of travel measured (a car that stops in
  // a jam keeps its camera's direction of travel when it moves again).
  Eigen::Matrix3d predicted_rotation_ = Eigen::Matrix3d::Identity();
  std::optional<Eigen::Vector3d> predicted_direction_;
};

}  // namespace roadscale
