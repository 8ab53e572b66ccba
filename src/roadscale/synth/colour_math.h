#pragma once

#include <algorithm>

#include "roadscale/synth/mesh.h"

namespace roadscale::synth {

// 0 below edge0, 1 above edge1, a smooth cubic between.
inline double SmoothStep(double edge0, double edge1, double x) {
  const double t = std::min(1.0, std::max(0.0, (x - edge0) / (edge1 - edge0)));
  return t * t * (3.0 - 2.0 * t);
}

// a at k = 0, b at k = 1.
inline Rgb Mix(const Rgb& a, const Rgb& b, double k) {
  return {static_cast<float>(a.r + (b.r - a.r) * k), static_cast<float>(a.g + (b.g - a.g) * k),
          static_cast<float>(a.b + (b.b - a.b) * k)};
}

}  // namespace roadscale::synth
