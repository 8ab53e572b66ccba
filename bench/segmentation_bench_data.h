#pragma once

// What the segmentation benchmark programs read: the shipped model files and the shared
// KITTI frames (ROADSCALE_SHARED, default ../shared beside the project).

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace roadscale {

// config/models/espnetv2_<size>.yaml, e.g. size "512x256".
std::string ShippedModelYaml(const std::string& size);

// One of the 5 labelled KITTI images of shared/kitti_semantics/training.
struct LabelledImage {
  std::string name;  // e.g. 000000_10.png
  cv::Mat colour;    // BGR
  cv::Mat grey;
  // Ground truth in Cityscapes train ids, resized (nearest) to the image as the files are
  // published (their labels are 1242x375, the images 1224x370).
  cv::Mat truth;
};

// The 5 labelled images; throws Error naming the first file it cannot read.
std::vector<LabelledImage> ReadLabelledKittiImages();

// Frame `index` of the shared KITTI 00 (grey image_0); throws Error naming it if unreadable.
cv::Mat ReadKitti00Frame(int index);

}  // namespace roadscale
