#pragma once

#include <memory>
#include <string>

#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// The default network, relative to the project's source folder: ESPNetv2 at 512x256 gives the
// grey KITTI frames a road mask as good as the larger inputs at less than half their time
// (docs/benchmark-history.md, "Segmentation").
inline constexpr char kDefaultSegmentationModel[] = "config/models/espnetv2_512x256.yaml";

struct SegmentationOptions {
  // A segmentation model YAML (see segmentation_model.h), or "none" for no segmentation.
  std::string model = "none";
  // Segment every k-th frame and reuse the masks in between; 1 (the paper: every frame).
  int every = 1;
  // Threads OpenCV DNN uses for a network; 1.
  int dnn_threads = 1;
  // Frames segmented at the same time, each by its own copy of the segmenter (`roadscale run`
  // in threads; 1 when `every` > 1, whose reuse of masks needs the frames in turn). OpenCV DNN
  // spreads one ESPNetv2 512x256 inference over 2 threads at 1.47x the speed of 1 (92 ms
  // instead of 135 ms): two single-threaded networks on two frames keep both cores busier
  // (docs/benchmark-history.md, "System").
  int workers = 2;
  MaskOptions masks;

  void Check() const;
};

// The segmenter `options.model` describes, wrapped to run every k-th frame when every > 1.
// Every check that can fail on a model (file, YAML keys, loading the network, its output
// shape) runs here, before any frame is processed; throws Error naming the file.
std::unique_ptr<Segmenter> MakeSegmenter(const SegmentationOptions& options);

}  // namespace roadscale
