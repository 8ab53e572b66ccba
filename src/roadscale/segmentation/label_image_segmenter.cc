#include "roadscale/segmentation/label_image_segmenter.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "roadscale/io/image_file.h"
#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::string SizeText(const cv::Size& size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

}  // namespace

cv::Size ReadPngSize(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) ThrowFileError(path, "label image not found");
  // 8-byte signature, then the IHDR chunk: length (4), "IHDR" (4), width (4), height (4),
  // both big-endian.
  std::array<unsigned char, 24> header{};
  file.read(reinterpret_cast<char*>(header.data()), header.size());
  static const std::array<unsigned char, 8> kSignature = {0x89, 'P',  'N',  'G',
                                                          '\r', '\n', 0x1a, '\n'};
  if (!file || !std::equal(kSignature.begin(), kSignature.end(), header.begin()) ||
      std::string(header.begin() + 12, header.begin() + 16) != "IHDR") {
    ThrowFileError(path, "not a PNG file; expected an 8-bit single-channel label PNG");
  }
  const auto big_endian = [&header](int offset) {
    return static_cast<int>((static_cast<uint32_t>(header[offset]) << 24) |
                            (static_cast<uint32_t>(header[offset + 1]) << 16) |
                            (static_cast<uint32_t>(header[offset + 2]) << 8) |
                            static_cast<uint32_t>(header[offset + 3]));
  };
  return {big_endian(16), big_endian(20)};
}

LabelImageSegmenter::LabelImageSegmenter(const SegmentationModel& model, const MaskOptions& masks)
    : model_(model), masks_(masks) {
  masks_.Check();
  model_.classes.Check();
  CheckOption(model_.backend == SegmentationBackend::kLabelImages, "model",
              model_.yaml_path + " does not describe label images");
  if (!std::filesystem::is_directory(model_.label_images.folder)) {
    ThrowFileError(model_.label_images.folder.string(),
                   "label folder not found (named in " + model_.yaml_path + ")");
  }
}

std::string LabelImageSegmenter::LabelPath(const std::string& frame_name) const {
  return (model_.label_images.folder / (frame_name + ".png")).string();
}

void LabelImageSegmenter::CheckFrames(const std::vector<std::string>& frame_names,
                                      const cv::Size& image_size) const {
  for (const std::string& name : frame_names) {
    const std::string path = LabelPath(name);
    if (!std::filesystem::is_regular_file(path)) {
      ThrowFileError(path, "label image of frame " + name + " not found (label folder named in " +
                               model_.yaml_path + ")");
    }
    const cv::Size size = ReadPngSize(path);
    if (!model_.label_images.resize && size != image_size) {
      ThrowFileError(path, "label image is " + SizeText(size) + ", expected the frame's size " +
                               SizeText(image_size) + " (or resize: true in " + model_.yaml_path +
                               ")");
    }
  }
}

cv::Mat LabelImageSegmenter::Labels(const std::string& frame_name,
                                    const cv::Size& image_size) const {
  const std::string path = LabelPath(frame_name);
  if (!std::filesystem::is_regular_file(path)) {
    ThrowFileError(path, "label image of frame " + frame_name +
                             " not found (label folder named in " + model_.yaml_path + ")");
  }
  const cv::Mat raw = ReadImageFile(path, cv::IMREAD_UNCHANGED, "label image");
  if (raw.type() != CV_8UC1) {
    ThrowFileError(path, "a label image must be 8-bit with one channel");
  }
  cv::Mat labels = raw;
  if (model_.label_images.ids == LabelIdSpace::kCityscapesLabelIds) {
    cv::LUT(raw, CityscapesLabelIdToTrainIdTable(), labels);
  }
  if (labels.size() != image_size) {
    if (!model_.label_images.resize) {
      ThrowFileError(path, "label image is " + SizeText(labels.size()) +
                               ", expected the frame's size " + SizeText(image_size) +
                               " (or resize: true in " + model_.yaml_path + ")");
    }
    cv::resize(labels, labels, image_size, 0.0, 0.0, cv::INTER_NEAREST);
  }
  return labels;
}

SegmentationResult LabelImageSegmenter::Segment(const cv::Mat& image,
                                                const std::string& frame_name) {
  const auto start = std::chrono::steady_clock::now();
  const cv::Mat labels = Labels(frame_name, image.size());
  const double milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  SegmentationResult result = DeriveMasks(labels, model_.classes, masks_);
  result.milliseconds = milliseconds;
  return result;
}

std::string LabelImageSegmenter::Description() const {
  return std::string("label images ") + model_.label_images.folder.string() + " (" +
         (model_.label_images.ids == LabelIdSpace::kTrainIds ? "train ids" : "label ids") + ")";
}

}  // namespace roadscale
