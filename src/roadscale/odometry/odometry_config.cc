#include "roadscale/odometry/odometry_config.h"

#include "roadscale/segmentation/label_image_segmenter.h"
#include "roadscale/segmentation/make_segmenter.h"
#include "roadscale/segmentation/segmentation_model.h"
#include "roadscale/util/error.h"

namespace roadscale {

OdometryOptions OdometryOptionsFromConfig(const RunConfig& config, const CameraSetup& camera) {
  OdometryOptions options;
  options.camera = camera;
  options.pipeline = config.pipeline;
  options.pipeline.road_selection = config.scale;
  options.pipeline.road_selection.camera_height = camera.h0;
  options.run.opencv_threads = config.segmentation.dnn_threads;
  return options;
}

std::string ResolveDefaultModel(const std::string& default_model, RunConfig* config) {
  SegmentationOptions& options = config->segmentation;
  if (!config->labels.empty() || options.model != "default") return "";
  try {
    ReadSegmentationModel(default_model);
    options.model = default_model;
    return "";
  } catch (const Error& error) {
    options.model = "none";
    return "segmentation off: model not found at " + default_model + " (" + error.what() + ")";
  }
}

std::vector<std::unique_ptr<Segmenter>> MakeConfigSegmenters(const RunConfig& config) {
  std::vector<std::unique_ptr<Segmenter>> segmenters;
  const SegmentationOptions& options = config.segmentation;
  options.Check();
  if (!config.labels.empty()) {
    SegmentationModel model;
    model.yaml_path = config.labels;
    model.backend = SegmentationBackend::kLabelImages;
    model.label_images.folder = config.labels;
    model.label_images.ids = LabelIdSpace::kTrainIds;
    segmenters.push_back(std::make_unique<LabelImageSegmenter>(model, options.masks));
    return segmenters;
  }
  if (options.model == "none") return segmenters;
  const int copies = options.every == 1 ? options.workers : 1;
  for (int copy = 0; copy < copies; ++copy) segmenters.push_back(MakeSegmenter(options));
  return segmenters;
}

std::vector<Segmenter*> Pointers(const std::vector<std::unique_ptr<Segmenter>>& segmenters) {
  std::vector<Segmenter*> pointers;
  for (const std::unique_ptr<Segmenter>& segmenter : segmenters) {
    pointers.push_back(segmenter.get());
  }
  return pointers;
}

}  // namespace roadscale
