#include "roadscale/segmentation/segmentation_masks.h"

#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

void CheckIds(const std::vector<int>& ids, const char* name) {
  for (const int id : ids) {
    CheckOption(id >= 0 && id < 255, name,
                "class ids must be in 0..254 (255 means unknown), got " + std::to_string(id));
  }
}

cv::Mat Disc(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
}

}  // namespace

void MaskClasses::Check() const {
  CheckOption(!road_ids.empty(), "road_ids", "at least one road class id is needed");
  CheckIds(road_ids, "road_ids");
  CheckIds(dynamic_ids, "dynamic_ids");
}

void MaskOptions::Check() const {
  CheckOption(dynamic_dilation_px >= 0, "dynamic_dilation_px", "must be >= 0");
  CheckOption(road_erosion_px >= 0, "road_erosion_px", "must be >= 0");
}

bool PixelOnMask(const cv::Mat& mask, const Eigen::Vector2d& p) {
  const int x = static_cast<int>(std::lround(p.x()));
  const int y = static_cast<int>(std::lround(p.y()));
  return x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<unsigned char>(y, x) != 0;
}

cv::Mat LabelsInSet(const cv::Mat& labels, const std::vector<int>& ids) {
  CheckOption(labels.type() == CV_8UC1, "labels", "a label map must be CV_8U");
  cv::Mat table(1, 256, CV_8U, cv::Scalar(0));
  for (const int id : ids) {
    if (id >= 0 && id < 256) table.at<uchar>(id) = 255;
  }
  cv::Mat mask;
  cv::LUT(labels, table, mask);
  return mask;
}

SegmentationResult DeriveMasks(const cv::Mat& labels, const MaskClasses& classes,
                               const MaskOptions& options) {
  SegmentationResult result;
  result.labels = labels;
  result.dynamic_mask = options.use_dynamic_mask ? LabelsInSet(labels, classes.dynamic_ids)
                                                 : cv::Mat::zeros(labels.size(), CV_8UC1);
  if (options.use_dynamic_mask && options.dynamic_dilation_px > 0) {
    cv::dilate(result.dynamic_mask, result.dynamic_mask, Disc(options.dynamic_dilation_px));
  }
  cv::bitwise_not(result.dynamic_mask, result.static_mask);
  result.road_mask = LabelsInSet(labels, classes.road_ids);
  if (options.road_erosion_px > 0) {
    // Pixels outside the image count as road here: the image border is not a road edge.
    cv::erode(result.road_mask, result.road_mask, Disc(options.road_erosion_px), cv::Point(-1, -1),
              1, cv::BORDER_CONSTANT, cv::Scalar(255));
  }
  return result;
}

}  // namespace roadscale
