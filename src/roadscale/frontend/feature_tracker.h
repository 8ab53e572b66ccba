#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/frontend/feature_detector.h"
#include "roadscale/frontend/klt_tracker.h"

#include <Eigen/Core>

namespace roadscale {

// A feature followed through consecutive frames.
struct Track {
  int64_t id = 0;       // unique within a FeatureTracker, increasing in order of birth
  int first_frame = 0;  // frame index of pixels.front()
  // Pixel position in every frame from first_frame to last_frame(), with no gaps.
  std::vector<Eigen::Vector2d> pixels;

  int last_frame() const { return first_frame + static_cast<int>(pixels.size()) - 1; }
  int length() const { return static_cast<int>(pixels.size()); }
};

struct FeatureTrackerOptions {
  FeatureDetectorOptions detector;
  KltOptions klt;
  // Detection is the expensive step (SIFT at half resolution: ~30 ms a KITTI frame, KLT of
  // all tracks ~20 ms), so new features are detected only when fewer than `redetect_below`
  // tracks survive. On KITTI and the synthetic streets about 30 % of the tracks are lost
  // each frame (foliage, the fast-moving road in front, the image border), so 300 - still a
  // few hundred correspondences for the essential matrix - re-detects every second or third
  // frame in town; 400 and 600 re-detect every frame with the same accuracy (200-frame
  // synthetic runs in docs/benchmark-history.md).
  int redetect_below = 300;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// What one AddFrame call did, for the per-frame record.
struct TrackerFrameStats {
  int tracked = 0;          // tracks carried over from the previous frame
  int lost = 0;             // tracks that failed KLT, the forward-backward check or left the image
  int dropped_dynamic = 0;  // tracks that landed on the dynamic mask
  int detected = 0;         // new tracks started in this frame
  double pyramid_ms = 0.0;
  double tracking_ms = 0.0;
  double detection_ms = 0.0;
};

// Follows features from frame to frame: KLT with a forward-backward check, re-detection on a
// grid when the tracks run low. Frames must come in order; the tracker keeps the previous
// frame's pyramid.
class FeatureTracker {
 public:
  explicit FeatureTracker(const FeatureTrackerOptions& options);

  // Tracks the live tracks into `image` (grey CV_8UC1, every frame the same size) and returns
  // the number that survived. `dynamic_mask` (CV_8UC1, non-zero = moving object; empty =
  // none): tracks landing there are dropped. `prediction`: a pixel homography from the
  // previous frame to this one where KLT starts its search (identity: no prediction). Throws
  // Error on a bad image or mask, or a frame index that does not follow the previous one.
  int Track(int frame_index, const cv::Mat& image, const cv::Mat& dynamic_mask,
            const Eigen::Matrix3d& prediction = Eigen::Matrix3d::Identity());

  // Ends the tracks whose pixel in the current frame lies on `dynamic_mask` (as Track does with
  // its mask), counting them as dropped_dynamic: for masks known only after tracking (masks
  // carried from an earlier frame through the tracks' motion). Throws Error on a mask of the
  // wrong type or size.
  void DropOnMask(const cv::Mat& dynamic_mask);

  // Ends the tracks whose pixel in the earlier frame `frame_index` lay on that frame's own
  // `dynamic_mask`, counting them as dropped_dynamic, and returns their ids: for a mask that
  // arrives frames late (the network runs beside the tracking). A track born on a car after
  // the last segmented frame is off the carried mask once the car drives on; its pixel in
  // the segmented frame tells. Throws Error on a mask of the wrong type or size.
  std::vector<int64_t> DropOnMaskAt(int frame_index, const cv::Mat& dynamic_mask);

  // Starts new tracks in the current frame where `detection_mask` (CV_8UC1, non-zero =
  // allowed; empty = whole image) allows, when fewer than redetect_below tracks are alive
  // (or always with force). `road_mask` (empty: none known) gives the road's cells their own
  // cap (FeatureDetectorOptions::road_max_per_cell). Returns the number of new tracks.
  int Detect(const cv::Mat& detection_mask, bool force = false,
             const cv::Mat& road_mask = cv::Mat());

  // Ends the tracks with these ids (e.g. the two-view outliers).
  void Drop(const std::vector<int64_t>& ids);

  // The live tracks; each has its last pixel in the current frame.
  const std::vector<roadscale::Track>& tracks() const { return tracks_; }
  int current_frame() const { return current_frame_; }
  const TrackerFrameStats& stats() const { return stats_; }

 private:
  FeatureTrackerOptions options_;
  FeatureDetector detector_;
  std::vector<roadscale::Track> tracks_;
  KltPyramid pyramid_;
  cv::Mat image_;
  int current_frame_ = -1;
  int64_t next_id_ = 0;
  TrackerFrameStats stats_;
};

}  // namespace roadscale
