#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/segmentation/segmentation_result.h"

#include <Eigen/Core>

namespace roadscale {

// Which train ids make each mask. The defaults are the Cityscapes ones the paper uses.
struct MaskClasses {
  std::vector<int> road_ids = {0};
  std::vector<int> dynamic_ids = {11, 12, 13, 14, 15, 16, 17, 18};

  // Ids in 0..254, at least one road id.
  void Check() const;
};

struct MaskOptions {
  // Radius in pixels by which the dynamic mask grows (a (2r+1) x (2r+1) ellipse). The paper
  // does not give one; 5 px keeps SIFT's support regions (about 4 sigma) on a moving car's
  // edge out of the static mask at KITTI resolution. 0 disables.
  int dynamic_dilation_px = 5;
  // False: no pixel is dynamic (features anywhere, no track dropped for landing on a moving
  // object): the ablation of the paper's dynamic-object mask, with the road mask kept.
  bool use_dynamic_mask = true;
  // Radius in pixels by which the road mask shrinks, so that points on kerbs are not taken.
  // 0 (the paper: the road mask is used as the network gives it).
  int road_erosion_px = 0;

  void Check() const;
};

// Whether pixel `p`, rounded, lies inside `mask` (CV_8UC1) on its non-zero part.
bool PixelOnMask(const cv::Mat& mask, const Eigen::Vector2d& p);

// 255 where the label is one of `ids`, else 0.
cv::Mat LabelsInSet(const cv::Mat& labels, const std::vector<int>& ids);

// Builds the dynamic, static and road masks of a label map (CV_8U train ids); `labels` is
// kept in the result (shared, not copied).
SegmentationResult DeriveMasks(const cv::Mat& labels, const MaskClasses& classes,
                               const MaskOptions& options);

}  // namespace roadscale
