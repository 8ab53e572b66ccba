#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace roadscale {

// Intersection and union of the pixels whose label is in a class set, counted over the
// pixels the ground truth knows (ground truth != ignore_id), as the Cityscapes benchmark
// counts. Accumulates over several images.
struct ClassSetIou {
  double intersection = 0.0;
  double union_ = 0.0;

  // NaN when no pixel of the set is in either map.
  double Iou() const;
  // Adds one image pair: prediction and ground truth, CV_8U train ids, same size.
  void Add(const cv::Mat& predicted, const cv::Mat& truth, const std::vector<int>& ids,
           int ignore_id = 255);
};

// IoU of two binary masks (CV_8U, nonzero = set); NaN when both are empty.
double MaskIou(const cv::Mat& a, const cv::Mat& b);

// MaskIou pooled over several mask pairs: intersections and unions summed, then divided.
struct PooledMaskIou {
  double intersection = 0.0;
  double union_ = 0.0;

  // Adds one pair of binary masks (CV_8U, nonzero = set) of the same size.
  void Add(const cv::Mat& a, const cv::Mat& b);
  // NaN when every pair was empty.
  double Iou() const;
};

}  // namespace roadscale
