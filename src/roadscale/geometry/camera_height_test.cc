#include "roadscale/geometry/camera_height.h"

#include <limits>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(CameraHeight, AcceptsVehicleHeightsAndRejectsTheRest) {
  EXPECT_NO_THROW(CheckCameraHeight(1.65, "h0"));
  EXPECT_NO_THROW(CheckCameraHeight(kMaxCameraHeightM, "h0"));
  EXPECT_NO_THROW(CheckCameraHeight(kMinCameraHeightM, "h0"));
  for (double bad :
       {0.0, -1.65, 1650.0, 1e308, 1e-300, 0.001, std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(CheckCameraHeight(bad, "h0"), Error) << bad;
  }
  try {
    CheckCameraHeight(1e308, "h0");
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "invalid option h0: the camera height above the road must be in [0.05, 100] metres, "
              "got 1e+308");
  }
}

}  // namespace
}  // namespace roadscale
