#pragma once

#include <cstdint>
#include <deque>

#include <opencv2/core.hpp>

#include "roadscale/synth/scene_options.h"
#include "roadscale/util/random.h"

namespace roadscale::synth {

// Label images as a segmentation network gives them on real frames, made from a scene's exact
// labels: moving objects' outlines too small, late, or missing in a frame (the object then
// reads as road). Exact labels are what made the rendered traffic jams pass while a real jam
// segmented by the network lost its road (docs/synthetic_scenes.md, "Labels:").
class NetworkLikeLabels {
 public:
  NetworkLikeLabels(const LabelErrorOptions& options, uint64_t seed);

  // The next frame's labels (Cityscapes train ids, CV_8UC1) from its exact `labels`; frames
  // must come in order.
  cv::Mat Next(const cv::Mat& labels);

 private:
  LabelErrorOptions options_;
  Rng rng_;
  std::deque<cv::Mat> earlier_;  // exact labels of the last dynamic_lag_frames frames
};

}  // namespace roadscale::synth
