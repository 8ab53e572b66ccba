#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

void Segmenter::CheckFrames(const std::vector<std::string>& /*frame_names*/,
                            const cv::Size& /*image_size*/) const {}

SegmentationResult NoSegmenter::Segment(const cv::Mat& /*image*/,
                                        const std::string& /*frame_name*/) {
  return SegmentationResult();
}

std::string NoSegmenter::Description() const { return "none (no segmentation: no masks)"; }

}  // namespace roadscale
