#include "roadscale/segmentation/make_segmenter.h"

#include "roadscale/segmentation/interval_segmenter.h"
#include "roadscale/segmentation/label_image_segmenter.h"
#include "roadscale/segmentation/onnx_segmenter.h"
#include "roadscale/segmentation/segmentation_model.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::unique_ptr<Segmenter> MakeBackend(const SegmentationOptions& options) {
  if (options.model == "none") return std::make_unique<NoSegmenter>();
  const SegmentationModel model = ReadSegmentationModel(options.model);
  switch (model.backend) {
    case SegmentationBackend::kOnnx: {
      OnnxSegmenter::Options onnx_options;
      onnx_options.dnn_threads = options.dnn_threads;
      onnx_options.masks = options.masks;
      return std::make_unique<OnnxSegmenter>(model, onnx_options);
    }
    case SegmentationBackend::kLabelImages:
      return std::make_unique<LabelImageSegmenter>(model, options.masks);
    case SegmentationBackend::kNone:
      break;
  }
  return std::make_unique<NoSegmenter>();
}

}  // namespace

void SegmentationOptions::Check() const {
  CheckOption(!model.empty(), "model", "a segmentation model YAML or 'none' is needed");
  CheckOption(every >= 1, "every", "segment every k-th frame needs k >= 1");
  CheckOption(dnn_threads >= 1, "dnn_threads", "must be >= 1");
  CheckOption(workers >= 1 && workers <= 16, "segmentation.workers", "must be in [1, 16]");
  masks.Check();
}

std::unique_ptr<Segmenter> MakeSegmenter(const SegmentationOptions& options) {
  options.Check();
  std::unique_ptr<Segmenter> segmenter = MakeBackend(options);
  if (options.every == 1) return segmenter;
  return std::make_unique<IntervalSegmenter>(std::move(segmenter), options.every);
}

}  // namespace roadscale
