#pragma once

#include <memory>
#include <string>

#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// Runs another segmenter on every k-th call only (the first call always runs) and hands the
// last fresh result, marked fresh = false, to the frames in between. A frame whose image
// size differs from the last segmented one is always segmented. Costs accuracy where
// things move: see docs/benchmark-history.md, "Segmentation".
class IntervalSegmenter : public Segmenter {
 public:
  IntervalSegmenter(std::unique_ptr<Segmenter> segmenter, int every);

  SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) override;
  void CheckFrames(const std::vector<std::string>& frame_names,
                   const cv::Size& image_size) const override;
  std::string Description() const override;

 private:
  std::unique_ptr<Segmenter> segmenter_;
  int every_;
  int calls_since_fresh_ = 0;
  bool have_last_ = false;
  cv::Size last_size_;
  SegmentationResult last_;
};

}  // namespace roadscale
