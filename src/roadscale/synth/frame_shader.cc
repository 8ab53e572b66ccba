#include "roadscale/synth/frame_shader.h"

#include <algorithm>
#include <cmath>

#include "roadscale/synth/colour_math.h"
#include "roadscale/synth/texture_hash.h"

namespace roadscale::synth {
namespace {

constexpr Rgb kHorizon{0.86f, 0.89f, 0.93f};
constexpr Rgb kZenith{0.52f, 0.66f, 0.9f};

Rgb SkyColour(const Eigen::Vector3d& direction, uint32_t seed) {
  const double elevation = direction.z();
  Rgb sky = Mix(kHorizon, kZenith, SmoothStep(0.0, 0.6, elevation));
  if (elevation > 0.0) {
    // Clouds on a plane above the camera, fading towards the horizon.
    const double scale = 1.0 / (elevation + 0.05);
    const double x = direction.x() * scale, y = direction.y() * scale;
    const double cloud = FilteredFbm(x, y, 0.002 * scale, 0.6, 3, 0.55, seed);
    const double k = 0.5 * SmoothStep(-0.05, 0.25, cloud) * SmoothStep(0.02, 0.25, elevation);
    sky = Mix(sky, Rgb{0.95f, 0.95f, 0.96f}, k);
  }
  return sky;
}

// Share of direct sunlight blocked at road coordinates (u, l).
double GroundShadowAt(double u, double l, double footprint, const ShadingInputs& inputs) {
  const double soft = 0.06 + 0.5 * footprint;
  double cover = 0.0;
  if (inputs.shadows != nullptr && !inputs.shadows->empty()) {
    const std::vector<GroundShadow>& list = *inputs.shadows;
    // Shadows are at most ~15 m long: start where u_min >= u - 15.
    auto it = std::lower_bound(list.begin(), list.end(), u - 15.0,
                               [](const GroundShadow& s, double v) { return s.u_min < v; });
    for (; it != list.end() && it->u_min <= u + soft; ++it) {
      if (u > it->u_max + soft || l < it->l_min - soft || l > it->l_max + soft) continue;
      const double cu = SmoothStep(it->u_min - soft, it->u_min + soft, u) *
                        (1.0 - SmoothStep(it->u_max - soft, it->u_max + soft, u));
      const double cl = SmoothStep(it->l_min - soft, it->l_min + soft, l) *
                        (1.0 - SmoothStep(it->l_max - soft, it->l_max + soft, l));
      cover = std::max(cover, it->strength * cu * cl);
    }
  }
  if (inputs.tree_shadows != nullptr && !inputs.tree_shadows->empty()) {
    const std::vector<TreeShadow>& list = *inputs.tree_shadows;
    auto it = std::lower_bound(list.begin(), list.end(), u - 7.0,
                               [](const TreeShadow& s, double v) { return s.u < v; });
    for (; it != list.end() && it->u <= u + 7.0; ++it) {
      const double du = u - it->u, dl = l - it->l;
      const double d2 = du * du + dl * dl;
      const double r_max = 1.25 * it->radius + soft;
      if (d2 > r_max * r_max) continue;
      const double d = std::sqrt(d2);
      const double radius = it->radius * (0.8 + 0.45 * ValueNoise(0.8 * u, 0.8 * l, it->seed));
      const double edge = SmoothStep(radius + soft, radius - soft, d);
      // Light through gaps in the crown.
      const double gaps = FilteredFbm(u, l, footprint, 1.2, 3, 0.6, it->seed + 1);
      const double dapple = 1.0 - 0.6 * SmoothStep(0.05 - soft, 0.05 + soft, gaps);
      cover = std::max(cover, 0.85 * edge * dapple);
    }
  }
  return cover;
}

// Rounds half up, as lround does for the non-negative values that matter.
uint8_t ToByte(double v) { return static_cast<uint8_t>(std::clamp(v, 0.0, 255.0) + 0.5); }

// Approximately Gaussian noise with unit variance from a pixel hash (sum of 4 bytes).
double HashNoise(int x, int y, uint32_t seed) {
  const uint32_t h = Hash3(x, y, seed);
  const double sum =
      static_cast<double>((h & 0xff) + ((h >> 8) & 0xff) + ((h >> 16) & 0xff) + (h >> 24));
  return (sum / 255.0 - 2.0) * 1.7320508075688772;  // std of the sum of 4 U(0,1) is 1/sqrt(3)
}

}  // namespace

void ShadeRows(const ShadingInputs& inputs, int row_begin, int row_end, FrameImages* images) {
  const Rasterizer& rasterizer = *inputs.rasterizer;
  const PinholeCamera& camera = rasterizer.camera();
  const std::vector<ScreenTriangle>& triangles = rasterizer.triangles();
  const std::vector<int32_t>& ids = rasterizer.ids();
  const int width = camera.width;
  const bool colour = !images->colour.empty();
  const Rgb haze_colour{kHorizon.r * 0.97f, kHorizon.g * 0.97f, kHorizon.b * 0.97f};
  const double fade_start = 0.8 * inputs.far_distance;

  for (int y = row_begin; y < row_end; ++y) {
    uint8_t* grey_row = images->grey.ptr<uint8_t>(y);
    uint8_t* colour_row = colour ? images->colour.ptr<uint8_t>(y) : nullptr;
    uint8_t* label_row = images->labels.ptr<uint8_t>(y);
    uint16_t* depth_row = images->depth.ptr<uint16_t>(y);
    uint8_t* moving_row = images->moving.ptr<uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      const int32_t id = ids[static_cast<size_t>(y) * width + x];
      Rgb c;
      if (id < 0) {
        const Eigen::Vector3d ray((x - camera.cx) / camera.fx, (y - camera.cy) / camera.fy, 1.0);
        c = SkyColour((inputs.world_from_cam_rotation * ray).normalized(), inputs.sky_seed);
        label_row[x] = label::kSky;
        depth_row[x] = 0;
        moving_row[x] = 0;
      } else {
        const ScreenTriangle& t = triangles[id];
        const double inv_z = t.inv_z[0] * x + t.inv_z[1] * y + t.inv_z[2];
        const double z = 1.0 / inv_z;
        const double s = (t.s_z[0] * x + t.s_z[1] * y + t.s_z[2]) * z;
        const double tt = (t.t_z[0] * x + t.t_z[1] * y + t.t_z[2]) * z;
        // Derivatives of the texture coordinates per pixel (quotient rule).
        const double ds_dx = (t.s_z[0] - s * t.inv_z[0]) * z;
        const double ds_dy = (t.s_z[1] - s * t.inv_z[1]) * z;
        const double dt_dx = (t.t_z[0] - tt * t.inv_z[0]) * z;
        const double dt_dy = (t.t_z[1] - tt * t.inv_z[1]) * z;
        TexelQuery query;
        query.s = s;
        query.t = tt;
        query.footprint_s = std::max(std::abs(ds_dx), std::abs(ds_dy));
        query.footprint_t = std::max(std::abs(dt_dx), std::abs(dt_dy));
        const SurfaceStyle& style = *t.style;
        const Rgb albedo = MaterialAlbedo(style, query, *inputs.textures);
        double light = t.light;
        if (style.road_coords && inputs.textures->options.shadows) {
          const double shade =
              GroundShadowAt(s, tt, std::max(query.footprint_s, query.footprint_t), inputs);
          light = inputs.ambient + (light - inputs.ambient) * (1.0 - shade);
        }
        c = {static_cast<float>(albedo.r * light), static_cast<float>(albedo.g * light),
             static_cast<float>(albedo.b * light)};
        // Haze, and a fade to the horizon colour before the far limit cuts things off.
        const double clear = std::exp(-z / inputs.haze_distance) *
                             (1.0 - SmoothStep(fade_start, inputs.far_distance, z));
        c = Mix(haze_colour, c, clear);
        label_row[x] = style.label;
        moving_row[x] = t.moving ? 255 : 0;
        const double depth = std::round(z * 256.0);
        depth_row[x] = depth < 65535.5 ? static_cast<uint16_t>(depth) : 0;
      }
      const double gain = 255.0 * inputs.exposure;
      const double luminance = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
      const double sigma = inputs.noise_sigma;
      grey_row[x] = ToByte(gain * luminance +
                           (sigma > 0.0 ? sigma * HashNoise(x, y, inputs.noise_seed) : 0.0));
      if (colour) {
        const double channels[3] = {c.b, c.g, c.r};  // BGR
        for (int k = 0; k < 3; ++k) {
          const double noise =
              sigma > 0.0 ? sigma * HashNoise(x, y, inputs.noise_seed + 1 + k) : 0.0;
          colour_row[3 * x + k] = ToByte(gain * channels[k] + noise);
        }
      }
    }
  }
}

}  // namespace roadscale::synth
