#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "roadscale/segmentation/segmentation_masks.h"

namespace roadscale {

// A segmentation model file (YAML) says which backend to run and how to feed it, so that any
// network exported to ONNX, or labels computed by any tool, drop in without code changes.
// The keys, one mapping at the top level (unknown keys are errors):
//
//   backend: onnx | label_images | none
//   road_ids: [0]                 train ids that make the road mask (default [0])
//   dynamic_ids: [11, ..., 18]    train ids that make the dynamic mask (default 11..18)
//
// backend: onnx (run through OpenCV DNN)
//   file: models/espnetv2/x.onnx  see ResolveModelFile() for where a relative path is looked up
//   input_size: [W, H]            the network's fixed input size; images are resized to it
//   channel_order: rgb | bgr      the channel order the network expects (required)
//   input_channels: 3             3: grey images are replicated to 3 channels; 1: colour
//                                 images are converted to grey
//   scale: 1.0                    each channel value (0..255) is multiplied by scale,
//   mean: [0, 0, 0]               then has mean subtracted and is divided by std, both in
//   std: [1, 1, 1]                the network's channel order
//   output: scores | labels       scores: [1, C, h, w] floats, argmax over C; labels: one
//                                 class index a pixel, [1, h, w] or [1, 1, h, w]
//   num_classes: 20               C; checked against the network at load time
//   classes: [road, ...]          optional names, num_classes of them
//   train_ids: [0, 1, ...]        optional Cityscapes train id of each class index (255:
//                                 none); default: the class index is the train id
//
// backend: label_images (a folder of precomputed label PNGs, one per frame)
//   folder: labels/               relative to the YAML file's folder
//   ids: train_ids | label_ids    what the PNGs hold: Cityscapes train ids or label ids
//   resize: false                 true: a label image of another size than its frame is
//                                 resized to it (nearest neighbour); false: an error
//
// backend: none                   the "without segmentation" ablation; no other keys
enum class SegmentationBackend { kOnnx, kLabelImages, kNone };
enum class ChannelOrder { kRgb, kBgr };
enum class OutputLayout { kScores, kLabels };
enum class LabelIdSpace { kTrainIds, kCityscapesLabelIds };

struct OnnxModelSpec {
  std::filesystem::path file;  // resolved: the file that exists
  int input_width = 0;
  int input_height = 0;
  ChannelOrder channel_order = ChannelOrder::kRgb;
  int input_channels = 3;
  double scale = 1.0;
  std::array<double, 3> mean = {0.0, 0.0, 0.0};
  std::array<double, 3> std = {1.0, 1.0, 1.0};
  OutputLayout output = OutputLayout::kScores;
  int num_classes = 0;
  std::vector<std::string> class_names;
  std::vector<int> train_ids;  // empty: identity
};

struct LabelImageSpec {
  std::filesystem::path folder;  // resolved against the YAML file's folder
  LabelIdSpace ids = LabelIdSpace::kTrainIds;
  bool resize = false;
};

struct SegmentationModel {
  std::string yaml_path;
  SegmentationBackend backend = SegmentationBackend::kNone;
  OnnxModelSpec onnx;
  LabelImageSpec label_images;
  MaskClasses classes;
};

// Reads and checks a model file. Throws Error naming the file, the line when there is one,
// and what was expected, for a missing file, a YAML syntax error, an unknown or missing key,
// a wrong value, or a model file (.onnx) that does not exist.
SegmentationModel ReadSegmentationModel(const std::string& yaml_path);

// Where a model file named in a YAML file is: an absolute path as it is; a relative one
// beside the YAML file when it exists there, else under SharedDataDir() (so that the
// shipped config/models/*.yaml find ../shared/models/... wherever the project is built).
// Throws Error naming both places looked at when it is in neither.
std::filesystem::path ResolveModelFile(const std::string& yaml_path, const std::string& file);

}  // namespace roadscale
