#pragma once

#include <cstddef>
#include <string>

#include <opencv2/core.hpp>

#include "roadscale/frontend/mono_frontend.h"

namespace roadscale {

// What a scale source sees of one frame pair (the previous and the current frame).
struct ScaleQuery {
  // Index of the current frame in the whole input, and its position in this run (1 for the
  // second frame processed: a step always has a previous frame).
  size_t frame_index = 0;
  size_t position = 0;
  // The frontend's result for the current frame: tracks seen in both frames, the two-view
  // motion (rotation, unit direction, inlier ids) and its status.
  const FrontendFrame* frontend = nullptr;
  // Road mask of the previous image (CV_8UC1, non-zero = road), or empty without
  // segmentation.
  cv::Mat prev_road_mask;
};

struct ScaleResult {
  // False when the source has no length for this step (the pipeline then keeps the last one).
  bool valid = false;
  // True when the length was measured on this frame pair; false when a valid length is one
  // the source held from an earlier pair (the frame is then written as "held").
  bool measured = false;
  // Length in metres of the camera's translation from the previous to the current frame.
  double step_length_m = 0.0;
  // One word or phrase for the per-frame record ("oracle", "held: too few points", ...).
  std::string status;
  // The source's own columns of OUT/frames.csv (see DiagnosticsCsvHeader), comma-separated;
  // empty when the source has none for this frame.
  std::string diagnostics_csv;
};

// Where the metric length of each step comes from: the ground truth (oracle), the road plane
// (the paper's method), ... The pipeline asks once per frame pair, in order.
class ScaleSource {
 public:
  virtual ~ScaleSource() = default;
  // For logs and the run summary, e.g. "oracle".
  virtual std::string Name() const = 0;
  virtual ScaleResult StepLength(const ScaleQuery& query) = 0;
  // Names of the columns the source appends to OUT/frames.csv, comma-separated; empty for
  // none.
  virtual std::string DiagnosticsCsvHeader() const { return {}; }
};

}  // namespace roadscale
