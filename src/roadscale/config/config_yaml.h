#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "roadscale/pipeline/sequential_pipeline.h"
#include "roadscale/scale/scale_estimator.h"
#include "roadscale/segmentation/make_segmenter.h"

namespace roadscale {

// Every option of a `roadscale run`, as a config file gives it. The modules' option structs
// keep their own defaults (the paper's values); this file is the only place that knows their
// YAML names, so that the modules do not depend on a file format.
struct RunConfig {
  // Camera: the intrinsics (for --images / --video: all of fx fy cx cy width height, or
  // none), h0, the camera height above the road, and the lens's distortion (OpenCV's k1 k2 p1
  // p2 k3 k4 k5 k6, each optional; only with the intrinsics), so that config_used.yaml repeats
  // a run through a distorting lens.
  struct Camera {
    std::optional<double> fx, fy, cx, cy;
    std::optional<int> width, height;
    std::optional<double> h0;
    std::array<std::optional<double>, 8> distortion;
    bool HasIntrinsics() const { return fx.has_value(); }
    // As CameraSetup::distortion: none given is empty, k4..k6 make 8 coefficients, else 5.
    std::vector<double> Distortion() const;
    void SetDistortion(const std::vector<double>& coefficients);
  } camera;
  PipelineOptions pipeline;
  // Scale: "road" (the paper's method) or "oracle" (the ground truth's step lengths).
  std::string scale_source = "road";
  // camera_height is not read here: it is Camera.h0.
  ScaleEstimatorOptions scale;
  // Segmentation: model is a model YAML, "none", or "default" (the shared ESPNetv2 when it
  // is there, else none with a note); labels, when set, is a folder of label PNGs (train ids,
  // <frame name>.png) and replaces the model.
  SegmentationOptions segmentation;
  std::string labels;

  RunConfig() { segmentation.model = "default"; }
};

// Reads a config file over `config` (keys it does not name keep their values). The file has
// the blocks Camera:, Frontend:, Scale:, Mapping:, Segmentation:, each a mapping, each key optional
// (config/kitti.yaml lists them all with the paper's values). Throws Error naming the file
// and the line for a YAML syntax error, an unknown block or key, a key or block given twice,
// a value of the wrong type, or a value its option's Check() rejects.
void ReadRunConfig(const std::string& path, RunConfig* config);

// The config as a YAML file that ReadRunConfig reads back to the same values (doubles with
// round-trip precision), every key written.
std::string FormatRunConfig(const RunConfig& config);
// FormatRunConfig to `path`; throws Error naming the file when it cannot be written.
void WriteRunConfig(const std::string& path, const RunConfig& config);

}  // namespace roadscale
