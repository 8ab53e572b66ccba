#include "roadscale/config/rescale_config.h"

#include "roadscale/config/config_yaml.h"

namespace roadscale {

TrajectoryRescalerOptions RescalerOptionsFromConfig(const std::string& config_path) {
  TrajectoryRescalerOptions options;
  if (config_path.empty()) return options;
  RunConfig config;
  ReadRunConfig(config_path, &config);
  options.scale = config.scale;
  options.road_alignment = config.pipeline.mapping.road_alignment;
  options.alignment = config.pipeline.mapping.alignment;
  options.alignment_shadow_brightness = config.pipeline.mapping.road_alignment_shadow_brightness;
  return options;
}

}  // namespace roadscale
