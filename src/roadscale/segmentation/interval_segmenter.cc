#include "roadscale/segmentation/interval_segmenter.h"

#include <utility>

#include "roadscale/util/error.h"

namespace roadscale {

IntervalSegmenter::IntervalSegmenter(std::unique_ptr<Segmenter> segmenter, int every)
    : segmenter_(std::move(segmenter)), every_(every) {
  CheckOption(segmenter_ != nullptr, "segmenter", "a segmenter is needed");
  CheckOption(every_ >= 1, "every", "segment every k-th frame needs k >= 1");
}

SegmentationResult IntervalSegmenter::Segment(const cv::Mat& image, const std::string& frame_name) {
  const bool due = !have_last_ || calls_since_fresh_ + 1 >= every_ || image.size() != last_size_;
  if (!due) {
    ++calls_since_fresh_;
    SegmentationResult reused = last_;
    reused.milliseconds = 0.0;
    reused.fresh = false;
    return reused;
  }
  last_ = segmenter_->Segment(image, frame_name);
  last_size_ = image.size();
  have_last_ = true;
  calls_since_fresh_ = 0;
  return last_;
}

void IntervalSegmenter::CheckFrames(const std::vector<std::string>& frame_names,
                                    const cv::Size& image_size) const {
  segmenter_->CheckFrames(frame_names, image_size);
}

std::string IntervalSegmenter::Description() const {
  if (every_ == 1) return segmenter_->Description();
  return segmenter_->Description() + ", every " + std::to_string(every_) + " frames";
}

}  // namespace roadscale
