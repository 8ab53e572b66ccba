#include "roadscale/segmentation/onnx_segmenter.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// OpenCV's messages span several lines ("OpenCV(4.6.0) file:line: error: (-2:...) what in
// function ..."); the part after "error: " says what went wrong in one line.
std::string OneLine(const std::string& message) {
  std::string text = message;
  const size_t error = text.find("error: ");
  if (error != std::string::npos) text = text.substr(error + 7);
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string ShapeText(const cv::Mat& mat) {
  std::string text = "[";
  for (int i = 0; i < mat.dims; ++i) text += (i > 0 ? ", " : "") + std::to_string(mat.size[i]);
  return text + "]";
}

// Sets OpenCV's thread count for one scope; OpenCV's setting is global, so it is put back.
class ScopedNumThreads {
 public:
  explicit ScopedNumThreads(int threads) : previous_(cv::getNumThreads()) {
    cv::setNumThreads(threads);
  }
  ~ScopedNumThreads() { cv::setNumThreads(previous_); }
  ScopedNumThreads(const ScopedNumThreads&) = delete;
  ScopedNumThreads& operator=(const ScopedNumThreads&) = delete;

 private:
  int previous_;
};

}  // namespace

void OnnxSegmenter::Options::Check() const {
  CheckOption(dnn_threads >= 1, "dnn_threads", "must be >= 1");
  masks.Check();
}

OnnxSegmenter::OnnxSegmenter(const SegmentationModel& model, const Options& options)
    : model_(model), options_(options) {
  options_.Check();
  model_.classes.Check();
  CheckOption(model_.backend == SegmentationBackend::kOnnx, "model",
              model_.yaml_path + " does not describe an ONNX network");
  const OnnxModelSpec& spec = model_.onnx;
  const std::string file = spec.file.string();
  const std::string named_in = " (named in " + model_.yaml_path + ")";
  std::error_code error;
  if (!std::filesystem::is_regular_file(spec.file, error) ||
      std::filesystem::file_size(spec.file, error) == 0) {
    ThrowFileError(file, "missing or empty model file; expected an ONNX network" + named_in);
  }
  try {
    net_ = cv::dnn::readNet(file);
  } catch (const cv::Exception& e) {
    ThrowFileError(file, "OpenCV DNN cannot load this file as an ONNX network" + named_in + ": " +
                             OneLine(e.what()));
  }
  if (net_.empty()) {
    ThrowFileError(
        file, "OpenCV DNN loaded no layers from this file; expected an ONNX network" + named_in);
  }
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);

  train_id_table_ = cv::Mat(1, 256, CV_8U, cv::Scalar(kIgnoreTrainId));
  for (int c = 0; c < spec.num_classes; ++c) {
    train_id_table_.at<uchar>(c) =
        static_cast<uchar>(spec.train_ids.empty() ? c : spec.train_ids[c]);
  }

  // One inference now, so that a network with another output than the YAML says fails here,
  // before any frame is processed, and not in the middle of a run.
  const cv::Mat blank(spec.input_height, spec.input_width,
                      spec.input_channels == 3 ? CV_8UC3 : CV_8UC1, cv::Scalar::all(128));
  cv::Mat output;
  try {
    output = Forward(MakeBlob(blank));
  } catch (const cv::Exception& e) {
    ThrowFileError(file, "OpenCV DNN cannot run this network on a " +
                             std::to_string(spec.input_width) + "x" +
                             std::to_string(spec.input_height) + " input" + named_in + ": " +
                             OneLine(e.what()));
  }
  OutputLabels(output);
}

cv::Mat OnnxSegmenter::MakeBlob(const cv::Mat& image) const {
  const OnnxModelSpec& spec = model_.onnx;
  CheckOption(
      !image.empty() && image.depth() == CV_8U && (image.channels() == 1 || image.channels() == 3),
      "image", "segmentation needs an 8-bit grey or BGR image");
  cv::Mat converted = image;
  if (spec.input_channels == 3 && image.channels() == 1) {
    cv::cvtColor(image, converted, cv::COLOR_GRAY2BGR);
  } else if (spec.input_channels == 1 && image.channels() == 3) {
    cv::cvtColor(image, converted, cv::COLOR_BGR2GRAY);
  }
  if (spec.input_channels == 3 && spec.channel_order == ChannelOrder::kRgb) {
    cv::cvtColor(converted, converted, cv::COLOR_BGR2RGB);
  }
  const cv::Size input_size(spec.input_width, spec.input_height);
  cv::Mat resized;
  if (converted.size() == input_size) {
    resized = converted;
  } else {
    // Bilinear, as cv::dnn::blobFromImage resizes (the model card's recipe).
    cv::resize(converted, resized, input_size, 0.0, 0.0, cv::INTER_LINEAR);
  }
  std::vector<cv::Mat> channels;
  cv::split(resized, channels);
  for (size_t c = 0; c < channels.size(); ++c) {
    // (value * scale - mean) / std in one pass.
    channels[c].convertTo(channels[c], CV_32F, spec.scale / spec.std[c],
                          -spec.mean[c] / spec.std[c]);
  }
  cv::Mat normalised;
  cv::merge(channels, normalised);
  return cv::dnn::blobFromImage(normalised);
}

cv::Mat OnnxSegmenter::Forward(const cv::Mat& blob) {
  const ScopedNumThreads threads(options_.dnn_threads);
  net_.setInput(blob);
  return net_.forward();
}

cv::Mat OnnxSegmenter::OutputLabels(const cv::Mat& output) const {
  const OnnxModelSpec& spec = model_.onnx;
  const std::string where = spec.file.string();
  if (spec.output == OutputLayout::kScores) {
    if (output.dims != 4 || output.size[0] != 1 || output.size[1] != spec.num_classes ||
        output.type() != CV_32F) {
      ThrowFileError(where, "the network's output is " + ShapeText(output) + ", but " +
                                model_.yaml_path + " says output: scores with num_classes " +
                                std::to_string(spec.num_classes) + ": expected float [1, " +
                                std::to_string(spec.num_classes) + ", height, width]");
    }
    const int height = output.size[2];
    const int width = output.size[3];
    const int pixels = height * width;
    const float* scores = output.ptr<float>();
    cv::Mat best_score(height, width, CV_32F);
    cv::Mat labels(height, width, CV_8U, cv::Scalar(0));
    std::copy(scores, scores + pixels, best_score.ptr<float>());
    float* best = best_score.ptr<float>();
    uchar* label = labels.ptr<uchar>();
    for (int c = 1; c < spec.num_classes; ++c) {
      const float* plane = scores + static_cast<size_t>(c) * pixels;
      for (int i = 0; i < pixels; ++i) {
        if (plane[i] > best[i]) {
          best[i] = plane[i];
          label[i] = static_cast<uchar>(c);
        }
      }
    }
    cv::Mat train_ids;
    cv::LUT(labels, train_id_table_, train_ids);
    return train_ids;
  }

  const bool shape_ok = (output.dims == 3 && output.size[0] == 1) ||
                        (output.dims == 4 && output.size[0] == 1 && output.size[1] == 1);
  if (!shape_ok || output.channels() != 1) {
    ThrowFileError(where, "the network's output is " + ShapeText(output) + ", but " +
                              model_.yaml_path +
                              " says output: labels: expected [1, height, width] or "
                              "[1, 1, height, width]");
  }
  const int height = output.size[output.dims - 2];
  const int width = output.size[output.dims - 1];
  cv::Mat indices;
  cv::Mat(height, width, output.type(), const_cast<uchar*>(output.ptr()))
      .convertTo(indices, CV_32S);
  cv::Mat labels(height, width, CV_8U);
  for (int y = 0; y < height; ++y) {
    const int* in = indices.ptr<int>(y);
    uchar* out = labels.ptr<uchar>(y);
    for (int x = 0; x < width; ++x) {
      const int index = in[x];
      out[x] = index >= 0 && index < spec.num_classes ? train_id_table_.at<uchar>(index)
                                                      : static_cast<uchar>(kIgnoreTrainId);
    }
  }
  return labels;
}

cv::Mat OnnxSegmenter::Labels(const cv::Mat& image) {
  cv::Mat output;
  try {
    output = Forward(MakeBlob(image));
  } catch (const cv::Exception& e) {
    ThrowFileError(model_.onnx.file.string(), "inference failed: " + OneLine(e.what()));
  }
  const cv::Mat labels = OutputLabels(output);
  if (labels.size() == image.size()) return labels;
  cv::Mat resized;
  cv::resize(labels, resized, image.size(), 0.0, 0.0, cv::INTER_NEAREST);
  return resized;
}

SegmentationResult OnnxSegmenter::Segment(const cv::Mat& image, const std::string& /*frame_name*/) {
  const auto start = std::chrono::steady_clock::now();
  const cv::Mat labels = Labels(image);
  const double milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  SegmentationResult result = DeriveMasks(labels, model_.classes, options_.masks);
  result.milliseconds = milliseconds;
  return result;
}

std::string OnnxSegmenter::Description() const {
  const OnnxModelSpec& spec = model_.onnx;
  return "onnx " + spec.file.filename().string() + " (" + std::to_string(spec.input_width) + "x" +
         std::to_string(spec.input_height) + " input, " + std::to_string(spec.num_classes) +
         " classes, " + std::to_string(options_.dnn_threads) + " threads)";
}

}  // namespace roadscale
