#pragma once

#include <string>
#include <vector>

#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/segmentation/segmentation_model.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// Label maps computed beforehand by any tool (a user's own SegNeXt run, `roadscale segment`,
// ground truth): FOLDER/<frame name>.png, 8-bit single channel, holding Cityscapes train ids
// or label ids as the model YAML says.
class LabelImageSegmenter : public Segmenter {
 public:
  LabelImageSegmenter(const SegmentationModel& model, const MaskOptions& masks);

  // Reads the frame's label PNG. Throws Error naming the file when it is missing, not an
  // 8-bit single-channel image, or (unless the YAML says resize: true) not the image's size.
  SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) override;

  // Checks every frame's file exists and has `image_size` (from the PNG header, without
  // decoding), so that a run stops before its first frame rather than in the middle.
  void CheckFrames(const std::vector<std::string>& frame_names,
                   const cv::Size& image_size) const override;

  std::string Description() const override;

  // FOLDER/<frame_name>.png
  std::string LabelPath(const std::string& frame_name) const;

  // The frame's label map in train ids at `image_size` (see Segment), without masks.
  cv::Mat Labels(const std::string& frame_name, const cv::Size& image_size) const;

 private:
  SegmentationModel model_;
  MaskOptions masks_;
};

// Width and height of a PNG file from its header. Throws Error naming the file when it is
// missing or not a PNG.
cv::Size ReadPngSize(const std::string& path);

}  // namespace roadscale
