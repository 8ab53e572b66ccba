#pragma once

#include <functional>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/frontend/feature_tracker.h"
#include "roadscale/frontend/two_view_motion.h"
#include "roadscale/geometry/pinhole_camera.h"

namespace roadscale {

struct FrontendOptions {
  FeatureTrackerOptions tracker;
  TwoViewMotionOptions motion;
  // Start KLT where the previous frame's rotation moves each point (the infinite homography
  // K R K^-1): in a sharp turn the image shifts by tens of pixels, which the constant-position
  // guess leaves to the coarse pyramid levels.
  bool predict_with_rotation = true;
  // End the tracks that the essential matrix rejects (moving objects, KLT drift), so that
  // they neither reach the scale stage nor occupy grid cells at the next re-detection. Only
  // done for kOk frames: a degenerate frame's inlier set says nothing about a track.
  bool drop_outliers = true;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// A track's pixel in one frame.
struct TrackObservation {
  int64_t track_id = 0;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

// Everything the frontend measured in one frame.
struct FrontendFrame {
  int frame_index = 0;
  // Tracks seen in both the previous and this frame, before outliers were dropped.
  std::vector<Correspondence> correspondences;
  TwoViewMotion motion;
  TrackerFrameStats tracker;  // counts, and the pyramid/tracking/detection times
  double motion_ms = 0.0;
  int num_tracks = 0;  // live tracks after outlier removal and re-detection
  // Every live track's pixel in this frame after outlier removal and re-detection, in
  // increasing id order: what a map sees of the frame (new tracks included).
  std::vector<TrackObservation> observations;
  // Tracks found on a moving object only in a segmented earlier frame (FrontendMasks::
  // segmented_frame): their earlier observations were on it too, so a map drops them.
  std::vector<int64_t> late_dynamic_track_ids;
};

// The masks a frame's features obey (CV_8UC1 of the image's size; empty = none): where new
// features may start, and where tracks are dropped as moving objects.
struct FrontendMasks {
  cv::Mat detection_mask;
  cv::Mat dynamic_mask;
  // A segmented earlier frame whose own moving-object mask arrived with this frame (-1:
  // none): the tracks that were on it there are dropped too (FeatureTracker::DropOnMaskAt).
  int segmented_frame = -1;
  cv::Mat segmented_dynamic_mask = {};
  // The frame's road (empty: not known), where new features get the road's cap.
  cv::Mat road_mask = {};
};

// Gives a frame's masks once its tracks are followed into it: `correspondences` are the
// tracks seen in the previous and this frame (none in the first frame). Lets the masks be
// carried from an earlier segmented frame through the tracks' own motion.
using FrontendMaskProvider =
    std::function<FrontendMasks(const std::vector<Correspondence>& correspondences)>;

// The monocular frontend (the paper's "MonoVO" host): features on a grid, KLT tracking and
// the two-view motion of every frame. Frames must come in order.
class MonoFrontend {
 public:
  // Throws Error on invalid options or camera.
  MonoFrontend(const PinholeCamera& camera, const FrontendOptions& options);

  // Processes the next frame: `image` grey CV_8UC1 of the camera's size; `detection_mask`
  // where new features may start (non-zero = allowed; empty = whole image); `dynamic_mask`
  // where tracks are dropped (non-zero = moving object; empty = none). Throws Error on a bad
  // image or mask.
  FrontendFrame ProcessFrame(int frame_index, const cv::Mat& image,
                             const cv::Mat& detection_mask = cv::Mat(),
                             const cv::Mat& dynamic_mask = cv::Mat());
  // The same with the masks asked for after KLT, before any track is dropped or detected.
  FrontendFrame ProcessFrame(int frame_index, const cv::Mat& image,
                             const FrontendMaskProvider& masks_after_tracking);

  // The live tracks after the last frame, with their pixel histories.
  const std::vector<Track>& tracks() const { return tracker_.tracks(); }
  const PinholeCamera& camera() const { return camera_; }
  const FrontendOptions& options() const { return options_; }

 private:
  PinholeCamera camera_;
  FrontendOptions options_;
  FeatureTracker tracker_;
  Eigen::Matrix3d last_rotation_ = Eigen::Matrix3d::Identity();
};

}  // namespace roadscale
