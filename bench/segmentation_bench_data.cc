#include "segmentation_bench_data.h"

#include <cstdio>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/util/error.h"
#include "roadscale/util/shared_data.h"

namespace roadscale {

std::string ShippedModelYaml(const std::string& size) {
  return std::string(ROADSCALE_SOURCE_DIR) + "/config/models/espnetv2_" + size + ".yaml";
}

std::vector<LabelledImage> ReadLabelledKittiImages() {
  const std::string root = (SharedDataDir() / "kitti_semantics/training").string();
  std::vector<LabelledImage> images;
  for (int i = 0; i < 5; ++i) {
    LabelledImage image;
    image.name = "00000" + std::to_string(i) + "_10.png";
    image.colour = cv::imread(root + "/image_2/" + image.name, cv::IMREAD_COLOR);
    const cv::Mat label_ids = cv::imread(root + "/semantic/" + image.name, cv::IMREAD_UNCHANGED);
    if (image.colour.empty() || label_ids.type() != CV_8UC1) {
      throw Error(root + ": cannot read image or labels " + image.name);
    }
    cv::LUT(label_ids, CityscapesLabelIdToTrainIdTable(), image.truth);
    cv::resize(image.truth, image.truth, image.colour.size(), 0.0, 0.0, cv::INTER_NEAREST);
    cv::cvtColor(image.colour, image.grey, cv::COLOR_BGR2GRAY);
    images.push_back(std::move(image));
  }
  return images;
}

cv::Mat ReadKitti00Frame(int index) {
  char name[16];
  std::snprintf(name, sizeof(name), "%06d.png", index);
  const std::string path = (SharedDataDir() / "kitti/sequences/00/image_0" / name).string();
  const cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.empty()) throw Error(path + ": cannot read this frame");
  return image;
}

}  // namespace roadscale
