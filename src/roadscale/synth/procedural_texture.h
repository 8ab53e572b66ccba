#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "roadscale/synth/mesh.h"
#include "roadscale/synth/scene_options.h"
#include "roadscale/synth/texture_hash.h"

namespace roadscale::synth {

// A painted line along the road at lateral offset `l` (metres, left positive); dashed
// when gap > 0.
struct LaneMarking {
  double l = 0.0;
  double width = 0.12;
  double dash = 0.0;
  double gap = 0.0;
};

// Scene-wide inputs of the textures.
struct TextureContext {
  TextureOptions options;
  std::vector<LaneMarking> markings;
  uint32_t seed = 0;
};

// A surface point to colour: texture coordinates (metres) and the size of the pixel's
// footprint along s and t (metres), for filtering. Patterns finer than the footprint fade
// to their mean instead of aliasing, so that texture stays stable from frame to frame.
struct TexelQuery {
  double s = 0.0, t = 0.0;
  double footprint_s = 0.0, footprint_t = 0.0;
};

// The albedo (0..1 per channel) of a material at a surface point.
Rgb MaterialAlbedo(const SurfaceStyle& style, const TexelQuery& query,
                   const TextureContext& context);

// Building blocks, exposed for tests.
// floor() for the texture coordinates' range (|x| < 2^62): a conversion instead of a libm
// call, which the baseline x86-64 target would make.
inline double FastFloor(double x) {
  const double truncated = static_cast<double>(static_cast<int64_t>(x));
  return truncated > x ? truncated - 1.0 : truncated;
}

// Smooth value noise in [0, 1).
inline double ValueNoise(double x, double y, uint32_t seed) {
  const double fx = FastFloor(x), fy = FastFloor(y);
  const int32_t ix = static_cast<int32_t>(static_cast<int64_t>(fx));
  const int32_t iy = static_cast<int32_t>(static_cast<int64_t>(fy));
  double tx = x - fx, ty = y - fy;
  tx = tx * tx * (3.0 - 2.0 * tx);
  ty = ty * ty * (3.0 - 2.0 * ty);
  const double a = HashUnit(ix, iy, seed), b = HashUnit(ix + 1, iy, seed);
  const double c = HashUnit(ix, iy + 1, seed), d = HashUnit(ix + 1, iy + 1, seed);
  const double top = a + (b - a) * tx;
  const double bottom = c + (d - c) * tx;
  return top + (bottom - top) * ty;
}
// Sum of `octaves` value-noise octaves from `frequency` (cycles per metre), each doubling
// the frequency and scaling the amplitude by `gain`; octaves whose wavelength is below two
// footprints fade out. Result roughly in [-0.5, 0.5], mean 0.
double FilteredFbm(double x, double y, double footprint, double frequency, int octaves, double gain,
                   uint32_t seed);
// Share of [x - footprint/2, x + footprint/2] covered by the pulses [k p + offset,
// k p + offset + width] (a box-filtered pulse train).
double FilteredPulse(double x, double period, double width, double offset, double footprint);
// Share of [x - footprint/2, x + footprint/2] inside [low, high] (one box-filtered pulse).
inline double FilteredBox(double x, double low, double high, double footprint) {
  if (footprint < 1e-6) return (x >= low && x < high) ? 1.0 : 0.0;
  const double half = 0.5 * footprint;
  const double overlap = std::min(x + half, high) - std::max(x - half, low);
  return overlap > 0.0 ? overlap / footprint : 0.0;
}

}  // namespace roadscale::synth
