#include "roadscale/segmentation/cityscapes.h"

#include <array>

#include <opencv2/imgproc.hpp>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

struct TrainClass {
  const char* name;
  int label_id;
  cv::Vec3b rgb;
};

// The Cityscapes benchmark's definition (cityscapesScripts labels.py), in train-id order.
const std::array<TrainClass, kNumCityscapesTrainIds>& TrainClasses() {
  static const std::array<TrainClass, kNumCityscapesTrainIds> classes = {{
      {"road", 7, {128, 64, 128}},
      {"sidewalk", 8, {244, 35, 232}},
      {"building", 11, {70, 70, 70}},
      {"wall", 12, {102, 102, 156}},
      {"fence", 13, {190, 153, 153}},
      {"pole", 17, {153, 153, 153}},
      {"traffic light", 19, {250, 170, 30}},
      {"traffic sign", 20, {220, 220, 0}},
      {"vegetation", 21, {107, 142, 35}},
      {"terrain", 22, {152, 251, 152}},
      {"sky", 23, {70, 130, 180}},
      {"person", 24, {220, 20, 60}},
      {"rider", 25, {255, 0, 0}},
      {"car", 26, {0, 0, 142}},
      {"truck", 27, {0, 0, 70}},
      {"bus", 28, {0, 60, 100}},
      {"train", 31, {0, 80, 100}},
      {"motorcycle", 32, {0, 0, 230}},
      {"bicycle", 33, {119, 11, 32}},
      // Not a Cityscapes class: the 20th output of networks trained with a background class.
      {"background", -1, {0, 0, 0}},
  }};
  return classes;
}

}  // namespace

std::vector<int> CityscapesDynamicTrainIds() { return {11, 12, 13, 14, 15, 16, 17, 18}; }

std::string CityscapesTrainIdName(int train_id) {
  if (train_id < 0 || train_id >= kNumCityscapesTrainIds) return "ignore";
  return TrainClasses()[train_id].name;
}

cv::Mat CityscapesLabelIdToTrainIdTable() {
  cv::Mat table(1, 256, CV_8U, cv::Scalar(kIgnoreTrainId));
  for (int train_id = 0; train_id < kNumCityscapesTrainIds; ++train_id) {
    const int label_id = TrainClasses()[train_id].label_id;
    if (label_id >= 0) table.at<uchar>(label_id) = static_cast<uchar>(train_id);
  }
  return table;
}

cv::Vec3b CityscapesTrainIdColour(int train_id) {
  if (train_id < 0 || train_id >= kNumCityscapesTrainIds) return {0, 0, 0};
  const cv::Vec3b& rgb = TrainClasses()[train_id].rgb;
  return {rgb[2], rgb[1], rgb[0]};
}

cv::Mat ColouriseTrainIds(const cv::Mat& labels) {
  CheckOption(labels.type() == CV_8UC1, "labels", "a label map must be CV_8U");
  cv::Mat table(1, 256, CV_8UC3);
  for (int id = 0; id < 256; ++id) table.at<cv::Vec3b>(id) = CityscapesTrainIdColour(id);
  cv::Mat labels3;
  cv::cvtColor(labels, labels3, cv::COLOR_GRAY2BGR);
  cv::Mat colours;
  cv::LUT(labels3, table, colours);
  return colours;
}

cv::Mat OverlayTrainIds(const cv::Mat& image, const cv::Mat& labels, double colour_weight) {
  CheckOption(image.size() == labels.size(), "labels", "the label map must have the image's size");
  CheckOption(image.depth() == CV_8U && (image.channels() == 1 || image.channels() == 3), "image",
              "an overlay needs an 8-bit grey or BGR image");
  cv::Mat bgr;
  if (image.channels() == 1) {
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
  } else {
    bgr = image;
  }
  cv::Mat blended;
  cv::addWeighted(bgr, 1.0 - colour_weight, ColouriseTrainIds(labels), colour_weight, 0.0, blended);
  bgr.copyTo(blended, labels >= kNumCityscapesTrainIds);
  return blended;
}

}  // namespace roadscale
