#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/synth/procedural_texture.h"
#include "roadscale/synth/rasterizer.h"
#include "roadscale/synth/static_world.h"

#include <Eigen/Core>

namespace roadscale::synth {

// Everything the per-pixel pass needs besides the rasterized ids.
struct ShadingInputs {
  const Rasterizer* rasterizer = nullptr;
  const TextureContext* textures = nullptr;
  Eigen::Matrix3d world_from_cam_rotation = Eigen::Matrix3d::Identity();
  const std::vector<GroundShadow>* shadows = nullptr;     // sorted by u_min
  const std::vector<TreeShadow>* tree_shadows = nullptr;  // sorted by u
  double ambient = 0.5;
  double haze_distance = 350.0;
  double far_distance = 260.0;
  double exposure = 1.0;     // gain on the whole image
  double noise_sigma = 0.0;  // grey levels
  uint32_t noise_seed = 0;   // per frame
  uint32_t sky_seed = 0;     // per scene
};

// Output images; `colour` may be empty (not rendered).
struct FrameImages {
  cv::Mat grey;    // CV_8UC1
  cv::Mat colour;  // CV_8UC3, BGR
  cv::Mat labels;  // CV_8UC1, Cityscapes train ids
  cv::Mat depth;   // CV_16UC1, z in 1/256 m, 0 where nothing is nearer than 256 m
  cv::Mat moving;  // CV_8UC1, 255 on objects that move in the world at this instant, else 0
};

// Shades rows [row_begin, row_end): texture, light and shadow, haze, sky, exposure and
// noise. Each pixel depends only on its own inputs (noise is hashed from the pixel and the
// frame), so rows may be shaded by any number of threads with identical results.
void ShadeRows(const ShadingInputs& inputs, int row_begin, int row_end, FrameImages* images);

}  // namespace roadscale::synth
