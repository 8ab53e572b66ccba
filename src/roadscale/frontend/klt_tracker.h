#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace roadscale {

struct KltOptions {
  // Side of the square window (pixels) matched at each pyramid level. OpenCV's default.
  int window_size = 21;
  // Coarsest pyramid level (0 = full resolution only). With a 21 px window, 3 levels follow
  // motions of ~80 px: the road right in front of a car at KITTI speeds moves 30-40 px.
  int pyramid_levels = 3;
  // Stop iterating at a level after this many iterations or when the update is below
  // `epsilon` pixels.
  int max_iterations = 30;
  double epsilon = 0.01;
  // OpenCV's minimum eigenvalue of the window's gradient matrix (normalised by the window
  // area): windows without texture in two directions cannot be tracked and are dropped.
  double min_eigen_threshold = 1e-4;
  // Forward-backward check: tracked back from the current frame to the previous one, a point
  // must land within this many pixels of where it started. Rejects the drifting tracks
  // (occlusions, repeated texture) that a one-way KLT reports as successes.
  double max_forward_backward_error_px = 0.5;
  // Coarsest pyramid level of the backward pass (at most pyramid_levels). The pass starts at
  // the point's own start, so a right track comes back from the finest level alone, at 0.7 of
  // the KLT CPU; but a wrong track can then stall at its start and pass the check too (KITTI
  // 00: 1.8 % instead of 1.3 % of the correspondences fail the essential matrix), and on the
  // three rendered highways t_err grew from 3.7 / 4.9 / 6.2 % to 4.2 / 7.7 / 10.0 % while the
  // town drives gained (docs/benchmark-history.md, "CPU without the network"). Hence the whole
  // pyramid by default.
  int backward_pyramid_levels = 3;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// The image pyramid (with its gradients) of one frame, built once and used to track both into
// and out of the frame.
struct KltPyramid {
  std::vector<cv::Mat> levels;
  cv::Size size;
  bool empty() const { return levels.empty(); }
};

// Builds the pyramid of a grey CV_8UC1 image; throws Error on any other image.
KltPyramid BuildKltPyramid(const cv::Mat& image, const KltOptions& options);

struct KltResult {
  std::vector<cv::Point2f> points;            // position in the current frame
  std::vector<bool> ok;                       // tracked both ways, inside the image
  std::vector<float> forward_backward_error;  // pixels; meaningful where both ways succeeded
};

// Pyramidal Lucas-Kanade from `prev` to `cur`, then back from `cur` to `prev`. A point is
// ok when both directions converge, the return lands within max_forward_backward_error_px of
// its start and the tracked position lies inside the image. `predicted` (empty, or one per
// point) is the starting guess in the current frame, e.g. from the last frame's rotation.
KltResult TrackKlt(const KltPyramid& prev, const KltPyramid& cur,
                   const std::vector<cv::Point2f>& prev_points,
                   const std::vector<cv::Point2f>& predicted, const KltOptions& options);

}  // namespace roadscale
