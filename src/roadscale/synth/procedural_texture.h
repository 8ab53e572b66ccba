#pragma once

#include <cstdint>
#include <vector>

#include "roadscale/synth/mesh.h"
#include "roadscale/synth/scene_options.h"

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
// Smooth value noise in [0, 1).
double ValueNoise(double x, double y, uint32_t seed);
// Sum of `octaves` value-noise octaves from `frequency` (cycles per metre), each doubling
// the frequency and scaling the amplitude by `gain`; octaves whose wavelength is below two
// footprints fade out. Result roughly in [-0.5, 0.5], mean 0.
double FilteredFbm(double x, double y, double footprint, double frequency, int octaves, double gain,
                   uint32_t seed);
// Share of [x - footprint/2, x + footprint/2] covered by the pulses [k p + offset,
// k p + offset + width] (a box-filtered pulse train).
double FilteredPulse(double x, double period, double width, double offset, double footprint);

}  // namespace roadscale::synth
