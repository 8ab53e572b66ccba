#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/segmentation/segmentation_result.h"

namespace roadscale {

// One semantic segmentation backend: a network, precomputed label images, or none. Every
// backend gives Cityscapes train ids and the masks derived from them, so that the later
// stages never know which one ran. Not thread-safe: segment from one thread (the pipeline's
// segmentation stage), or give each thread its own segmenter.
class Segmenter {
 public:
  virtual ~Segmenter() = default;

  // Segments one 8-bit grey or BGR image. `frame_name` is the frame's file stem ("000042"
  // for KITTI): backends that read precomputed results look the frame up by it; networks
  // ignore it. Throws Error on an image or frame the backend cannot handle.
  virtual SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) = 0;

  // Checks, before any frame is processed, that every frame of a run can be segmented:
  // label-image backends check that each frame's file exists and has `image_size`.
  // Throws Error naming the first file that is missing or wrong.
  virtual void CheckFrames(const std::vector<std::string>& frame_names,
                           const cv::Size& image_size) const;

  // One line for logs: backend, model file, input size.
  virtual std::string Description() const = 0;
};

// The paper's "without segmentation" ablation: every result has no labels and no masks
// (empty Mats, see SegmentationResult), which every later stage accepts.
class NoSegmenter : public Segmenter {
 public:
  SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) override;
  std::string Description() const override;
};

}  // namespace roadscale
