#include "roadscale/frontend/mono_frontend.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "roadscale/util/error.h"

namespace roadscale {

void FrontendOptions::Check() const {
  tracker.Check();
  motion.Check();
}

MonoFrontend::MonoFrontend(const PinholeCamera& camera, const FrontendOptions& options)
    : camera_(camera), options_(options), tracker_(options.tracker) {
  camera_.Check();
  options_.Check();
}

FrontendFrame MonoFrontend::ProcessFrame(int frame_index, const cv::Mat& image,
                                         const cv::Mat& detection_mask,
                                         const cv::Mat& dynamic_mask) {
  return ProcessFrame(frame_index, image, [&](const std::vector<Correspondence>&) {
    return FrontendMasks{detection_mask, dynamic_mask};
  });
}

FrontendFrame MonoFrontend::ProcessFrame(int frame_index, const cv::Mat& image,
                                         const FrontendMaskProvider& masks_after_tracking) {
  if (image.cols != camera_.width || image.rows != camera_.height) {
    throw Error("frame " + std::to_string(frame_index) + ": image is " +
                std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                " but the camera is " + std::to_string(camera_.width) + "x" +
                std::to_string(camera_.height));
  }
  FrontendFrame frame;
  frame.frame_index = frame_index;
  const bool first = tracker_.current_frame() < 0;

  Eigen::Matrix3d prediction = Eigen::Matrix3d::Identity();
  if (options_.predict_with_rotation) {
    const Eigen::Matrix3d K = camera_.K();
    prediction = K * last_rotation_ * K.inverse();
  }
  tracker_.Track(frame_index, image, cv::Mat(), prediction);
  const auto correspondences = [&] {
    std::vector<Correspondence> out;
    for (const Track& track : tracker_.tracks()) {
      if (track.length() < 2) continue;
      out.push_back({track.id, track.pixels[track.pixels.size() - 2], track.pixels.back()});
    }
    return out;
  };
  const FrontendMasks masks = masks_after_tracking(correspondences());
  tracker_.DropOnMask(masks.dynamic_mask);
  if (masks.segmented_frame >= 0) {
    frame.late_dynamic_track_ids =
        tracker_.DropOnMaskAt(masks.segmented_frame, masks.segmented_dynamic_mask);
  }
  frame.correspondences = correspondences();

  const auto start = std::chrono::steady_clock::now();
  if (first) {
    frame.motion.status = MotionStatus::kFirstFrame;
  } else {
    frame.motion = EstimateTwoViewMotion(frame.correspondences, camera_, options_.motion);
  }
  frame.motion_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  if (options_.drop_outliers && frame.motion.status == MotionStatus::kOk) {
    std::vector<int64_t> inliers = frame.motion.inlier_track_ids;
    std::sort(inliers.begin(), inliers.end());
    std::vector<int64_t> outliers;
    for (const Correspondence& c : frame.correspondences) {
      if (!std::binary_search(inliers.begin(), inliers.end(), c.track_id)) {
        outliers.push_back(c.track_id);
      }
    }
    tracker_.Drop(outliers);
  }
  tracker_.Detect(masks.detection_mask, /*force=*/false, masks.road_mask);

  // The rotation predicts the next frame's; without a measurement, predict none.
  const MotionStatus status = frame.motion.status;
  last_rotation_ = status == MotionStatus::kOk || status == MotionStatus::kPureRotation
                       ? frame.motion.rotation
                       : Eigen::Matrix3d::Identity();
  frame.tracker = tracker_.stats();
  frame.num_tracks = static_cast<int>(tracker_.tracks().size());
  frame.observations.reserve(tracker_.tracks().size());
  for (const Track& track : tracker_.tracks()) {
    frame.observations.push_back({track.id, track.pixels.back()});
  }
  return frame;
}

}  // namespace roadscale
