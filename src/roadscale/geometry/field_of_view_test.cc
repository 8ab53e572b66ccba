#include "roadscale/geometry/field_of_view.h"

#include <limits>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(FieldOfView, AcceptsLensesAndRejectsUnitMistakes) {
  EXPECT_NO_THROW(CheckFocalLength(718.856, 1241, "fx"));  // KITTI
  EXPECT_NO_THROW(CheckFocalLength(120.0, 1241, "fx"));    // a wide-angle dash cam
  EXPECT_NO_THROW(CheckFocalLength(20000.0, 1241, "fx"));  // a long telephoto
  for (double bad :
       {1e308, 7.2e7, 1e-300, 1.0, 0.0, -718.0, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(CheckFocalLength(bad, 1241, "fx"), Error) << bad;
  }
  try {
    CheckFocalLength(7.2e7, 1241, "camera.fx");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "invalid option camera.fx: 7.2e+07 px over an image side of 1241 px is no lens's "
              "focal length (expected 54.29 to 1.422e+05 px: a field of view of 0.5 to 170 "
              "degrees)");
  }
}

}  // namespace
}  // namespace roadscale
