#include "roadscale/segmentation/label_iou.h"

#include <limits>

#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/util/error.h"

namespace roadscale {

double ClassSetIou::Iou() const {
  if (union_ <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  return intersection / union_;
}

void ClassSetIou::Add(const cv::Mat& predicted, const cv::Mat& truth, const std::vector<int>& ids,
                      int ignore_id) {
  CheckOption(predicted.size() == truth.size(), "labels",
              "prediction and ground truth must have the same size");
  const cv::Mat known = truth != ignore_id;
  const cv::Mat in_predicted = LabelsInSet(predicted, ids) & known;
  const cv::Mat in_truth = LabelsInSet(truth, ids);
  intersection += cv::countNonZero(in_predicted & in_truth);
  union_ += cv::countNonZero(in_predicted | in_truth);
}

double MaskIou(const cv::Mat& a, const cv::Mat& b) {
  CheckOption(a.size() == b.size(), "masks", "masks must have the same size");
  const cv::Mat set_a = a != 0;
  const cv::Mat set_b = b != 0;
  const double union_count = cv::countNonZero(set_a | set_b);
  if (union_count == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return cv::countNonZero(set_a & set_b) / union_count;
}

void PooledMaskIou::Add(const cv::Mat& a, const cv::Mat& b) {
  CheckOption(a.size() == b.size(), "masks", "masks must have the same size");
  const cv::Mat set_a = a != 0;
  const cv::Mat set_b = b != 0;
  intersection += cv::countNonZero(set_a & set_b);
  union_ += cv::countNonZero(set_a | set_b);
}

double PooledMaskIou::Iou() const {
  return union_ > 0.0 ? intersection / union_ : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace roadscale
