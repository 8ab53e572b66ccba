#pragma once

#include <string>

#include "roadscale/rescale/trajectory_rescaler.h"

namespace roadscale {

// The rescaler's options as `roadscale rescale --config PATH` takes them: the road selection
// of the config's Scale block and the road alignment of its Mapping block; everything else
// the rescaler's own defaults (FAST features, the refined motion). "" for the defaults.
// scale.camera_height is left for the caller (the camera's h0). Throws Error naming the file
// when it does not read.
TrajectoryRescalerOptions RescalerOptionsFromConfig(const std::string& config_path);

}  // namespace roadscale
