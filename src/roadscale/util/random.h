#pragma once

#include <cstdint>

namespace roadscale {

// A small, fully specified random generator (xoshiro256** seeded through splitmix64). The
// standard library's distributions are implementation-defined, so the RANSACs, the synthetic
// scenes and the simulated scale drifts draw every random number through this class: the
// same seed gives the same numbers, and the same poses, on every platform and compiler.
class Rng {
 public:
  explicit Rng(uint64_t seed);

  uint64_t NextU64();
  // Uniform in [0, 1).
  double Uniform();
  double Uniform(double low, double high) { return low + (high - low) * Uniform(); }
  // Uniform integer in [low, high].
  int UniformInt(int low, int high);
  bool Bernoulli(double probability) { return Uniform() < probability; }
  // Standard normal (Box-Muller).
  double Normal();
  // A generator for a sub-stream: changing how many numbers one part of the scene draws
  // does not change any other part.
  Rng Fork(uint64_t stream);

 private:
  uint64_t state_[4];
};

}  // namespace roadscale
