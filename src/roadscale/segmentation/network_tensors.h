#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "roadscale/segmentation/segmentation_model.h"

namespace roadscale {

// The network's input for an 8-bit grey or BGR image, as a model YAML describes it: grey and
// colour converted to the network's channel count, channels put in its order, resized
// (bilinear, as cv::dnn::blobFromImage does) to its input size, each channel turned into
// (value * scale - mean) / std; a float [1, C, H, W] blob. Throws Error on another image type.
cv::Mat MakeInputBlob(const cv::Mat& image, const OnnxModelSpec& spec);

// The label map (CV_8U train ids, at the output's own size) of a network output: argmax over
// the classes of [1, C, h, w] scores, or the class indexes of a [1, h, w] / [1, 1, h, w]
// label output; class indexes become train ids through spec.train_ids, and indexes outside
// 0..num_classes-1 become kIgnoreTrainId. Throws Error naming spec.file and `yaml_path` when
// the output's shape is not the one the YAML describes.
cv::Mat OutputToTrainIds(const cv::Mat& output, const OnnxModelSpec& spec,
                         const std::string& yaml_path);

}  // namespace roadscale
