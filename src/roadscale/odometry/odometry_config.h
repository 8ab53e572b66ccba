#pragma once

#include <memory>
#include <string>
#include <vector>

#include "roadscale/config/config_yaml.h"
#include "roadscale/io/camera_setup.h"
#include "roadscale/odometry/odometry.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// The Odometry's options from a run config (ReadRunConfig: config/kitti.yaml's blocks) and
// the camera, as `roadscale run` takes them: the road selection is the config's Scale block
// at the camera's h0, and OpenCV gets the network's thread count during the run.
OdometryOptions OdometryOptionsFromConfig(const RunConfig& config, const CameraSetup& camera);

// Resolves Segmentation.model "default" to `default_model` (a model YAML) when that file
// reads as a model, else to "none"; returns why in that case (the program says it), else "".
std::string ResolveDefaultModel(const std::string& default_model, RunConfig* config);

// The segmenters a run config asks for: the label images of config.labels, else the model of
// config.segmentation.model (a model YAML; "default" resolved to a path before) with one copy
// per segmentation worker (one when masks are reused over frames, `every` > 1, which needs
// the frames in turn), else none ("none"). Throws Error naming the file when a model cannot
// be loaded.
std::vector<std::unique_ptr<Segmenter>> MakeConfigSegmenters(const RunConfig& config);

// The raw pointers Odometry and RunPipeline take.
std::vector<Segmenter*> Pointers(const std::vector<std::unique_ptr<Segmenter>>& segmenters);

}  // namespace roadscale
