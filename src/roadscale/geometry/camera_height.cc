#include "roadscale/geometry/camera_height.h"

#include <cmath>
#include <cstdio>

#include "roadscale/util/error.h"

namespace roadscale {

void CheckCameraHeight(double h0, const char* option) {
  char text[160];
  std::snprintf(text, sizeof(text),
                "the camera height above the road must be in [%g, %g] metres, got %g",
                kMinCameraHeightM, kMaxCameraHeightM, h0);
  CheckOption(std::isfinite(h0) && h0 >= kMinCameraHeightM && h0 <= kMaxCameraHeightM, option,
              text);
}

}  // namespace roadscale
