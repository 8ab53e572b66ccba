#pragma once

#include <memory>
#include <string>

#include <opencv2/dnn.hpp>

#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/segmentation/segmentation_model.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// A semantic segmentation network in ONNX, run on the CPU through OpenCV DNN.
class OnnxSegmenter : public Segmenter {
 public:
  struct Options {
    // Threads OpenCV uses during inference (restored afterwards): 2 leaves the rest of the
    // pipeline room on small machines and is what docs/benchmark-history.md measures.
    int dnn_threads = 2;
    MaskOptions masks;

    void Check() const;
  };

  // Loads the network and runs one inference on a blank image to check that its output has
  // the layout and number of classes `model` says. Throws Error naming the .onnx file (and
  // the model YAML) when the file is not a network OpenCV can load or run, or when the
  // output is not what the YAML says.
  OnnxSegmenter(const SegmentationModel& model, const Options& options);

  SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) override;
  std::string Description() const override;

  // The network's label map (train ids) for an image, at the image's size, without masks.
  cv::Mat Labels(const cv::Mat& image);

 private:
  cv::Mat Forward(const cv::Mat& blob);

  SegmentationModel model_;
  Options options_;
  cv::dnn::Net net_;
};

}  // namespace roadscale
