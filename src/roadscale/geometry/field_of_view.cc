#include "roadscale/geometry/field_of_view.h"

#include <cmath>
#include <cstdio>

#include "roadscale/geometry/angles.h"
#include "roadscale/util/error.h"

namespace roadscale {

void CheckFocalLength(double focal_px, int side_px, const char* option) {
  const double side = side_px;
  const double shortest = side / (2.0 * std::tan(0.5 * kMaxFieldOfViewDeg * kRadiansPerDegree));
  const double longest = side / (2.0 * std::tan(0.5 * kMinFieldOfViewDeg * kRadiansPerDegree));
  char text[240];
  std::snprintf(text, sizeof(text),
                "%g px over an image side of %d px is no lens's focal length (expected %.4g to "
                "%.4g px: a field of view of %g to %g degrees)",
                focal_px, side_px, shortest, longest, kMinFieldOfViewDeg, kMaxFieldOfViewDeg);
  CheckOption(std::isfinite(focal_px) && focal_px >= shortest && focal_px <= longest, option, text);
}

}  // namespace roadscale
