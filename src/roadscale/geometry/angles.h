#pragma once

#include <cmath>

namespace roadscale {

inline constexpr double kRadiansPerDegree = M_PI / 180.0;
inline constexpr double kDegreesPerRadian = 180.0 / M_PI;

}  // namespace roadscale
