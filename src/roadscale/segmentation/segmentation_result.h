#pragma once

#include <opencv2/core.hpp>

namespace roadscale {

// What segmentation knows about one frame. Every mask is CV_8U with the image's size,
// 255 = set, 0 = not set.
//
// An EMPTY Mat means "no information" (the "without segmentation" ablation, or a model
// that does not give this mask), and every later stage must accept it:
//  - no static mask: detect features anywhere;
//  - no dynamic mask: treat nothing as moving;
//  - no road mask: do not preselect road points (every triangulated point is a candidate).
struct SegmentationResult {
  // Cityscapes train ids (0 road ... 18 bicycle, 19 background, 255 unknown).
  cv::Mat labels;
  // Pixels of objects that may move (person ... bicycle), dilated by a margin because
  // object borders move between frames and segmentation is soft there.
  cv::Mat dynamic_mask;
  // Where features may be detected: the complement of the dynamic mask.
  cv::Mat static_mask;
  // Road pixels, optionally eroded so that points on kerbs and road edges are not taken.
  cv::Mat road_mask;
  // Milliseconds spent producing `labels` (network inference or file reading); 0 when the
  // result was reused from an earlier frame.
  double milliseconds = 0.0;
  // False when the result is an earlier frame's, reused (see IntervalSegmenter).
  bool fresh = true;

  bool HasLabels() const { return !labels.empty(); }
};

}  // namespace roadscale
