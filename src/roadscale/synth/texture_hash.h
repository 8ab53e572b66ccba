#pragma once

#include <cstdint>

namespace roadscale::synth {

// Stateless integer hashes for procedural textures and per-pixel noise (inline: the
// textures call them several million times a frame).
inline uint32_t Hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
inline uint32_t Hash3(int32_t x, int32_t y, uint32_t seed) {
  return Hash32(static_cast<uint32_t>(x) * 0x8da6b343U + static_cast<uint32_t>(y) * 0xd8163841U +
                seed * 0xcb1ab31fU);
}
// Hash3 mapped to [0, 1).
inline float HashUnit(int32_t x, int32_t y, uint32_t seed) {
  return static_cast<float>(Hash3(x, y, seed) >> 8) * (1.0f / 16777216.0f);
}

}  // namespace roadscale::synth
