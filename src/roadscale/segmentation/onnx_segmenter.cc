#include "roadscale/segmentation/onnx_segmenter.h"

#include <chrono>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "roadscale/segmentation/network_tensors.h"
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

// Sets OpenCV's thread count for one scope; OpenCV's setting is global, so it is put back.
// Nothing is changed when the count is already right: changing it while another thread runs
// an OpenCV parallel loop (the pipeline's frontend thread) crashes OpenCV, so the threaded
// pipeline sets it once before its threads start.
class ScopedNumThreads {
 public:
  explicit ScopedNumThreads(int threads) : previous_(cv::getNumThreads()) {
    if (threads != previous_) cv::setNumThreads(threads);
  }
  ~ScopedNumThreads() {
    if (cv::getNumThreads() != previous_) cv::setNumThreads(previous_);
  }
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

  // One inference now, so that a network with another output than the YAML says fails here,
  // before any frame is processed, and not in the middle of a run.
  const cv::Mat blank(spec.input_height, spec.input_width,
                      spec.input_channels == 3 ? CV_8UC3 : CV_8UC1, cv::Scalar::all(128));
  cv::Mat output;
  try {
    output = Forward(MakeInputBlob(blank, spec));
  } catch (const cv::Exception& e) {
    ThrowFileError(file, "OpenCV DNN cannot run this network on a " +
                             std::to_string(spec.input_width) + "x" +
                             std::to_string(spec.input_height) + " input" + named_in + ": " +
                             OneLine(e.what()));
  }
  OutputToTrainIds(output, spec, model_.yaml_path);
}

cv::Mat OnnxSegmenter::Forward(const cv::Mat& blob) {
  const ScopedNumThreads threads(options_.dnn_threads);
  net_.setInput(blob);
  return net_.forward();
}

cv::Mat OnnxSegmenter::Labels(const cv::Mat& image) {
  cv::Mat output;
  try {
    output = Forward(MakeInputBlob(image, model_.onnx));
  } catch (const cv::Exception& e) {
    ThrowFileError(model_.onnx.file.string(), "inference failed: " + OneLine(e.what()));
  }
  const cv::Mat labels = OutputToTrainIds(output, model_.onnx, model_.yaml_path);
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
