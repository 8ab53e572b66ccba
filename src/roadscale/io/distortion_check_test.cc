#include "roadscale/io/distortion_check.h"

#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/error_of.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;

TEST(DistortionCheck, UsableLensesPass) {
  const PinholeCamera kitti = KittiOdometryCamera();
  EXPECT_NO_THROW(CheckDistortionMap(kitti, {}));
  EXPECT_NO_THROW(CheckDistortionMap(kitti, {-0.3, 0.09, 0, 0, 0}));  // synth's barrel lens
  EXPECT_NO_THROW(CheckDistortionMap(kitti, {0.2, 0, 0.001, -0.001, 0}));
  EXPECT_NO_THROW(CheckDistortionMap(kitti, {0.1, 0, 0, 0, 0, 0, 0, 0.02}));
}

TEST(DistortionCheck, TheCoefficientAtFaultIsNamed) {
  const PinholeCamera kitti = KittiOdometryCamera();
  EXPECT_THAT(ErrorOf([&] {
                CheckDistortionMap(kitti, {1e6, 0, 0, 0, 0});
              }),
              HasSubstr("invalid option camera.k1: 1e+06 leaves 100 % of the undistorted image "
                        "outside the lens's image"));
  EXPECT_THAT(ErrorOf([&] {
                CheckDistortionMap(kitti, {-0.28, 0.07, 0, 0, -1.0});
              }),
              HasSubstr("invalid option camera.k3: -1 folds the undistortion map"));
  EXPECT_THAT(ErrorOf([&] {
                CheckDistortionMap(kitti, {0, 0, 0, 0, 0, -1.5, 0, 0});
              }),
              HasSubstr("invalid option camera.k4: -1.5 makes the rational model's denominator"));
}

TEST(DistortionCheck, TheFirstCoefficientWithoutWhichTheLensPassesIsNamed) {
  const PinholeCamera kitti = KittiOdometryCamera();
  // k1 and k2 alone are barrel lenses; together they bend the map back before the corner.
  EXPECT_NO_THROW(CheckDistortionMap(kitti, {-0.25, 0, 0, 0, 0}));
  EXPECT_NO_THROW(CheckDistortionMap(kitti, {0, -0.15, 0, 0, 0}));
  EXPECT_THAT(ErrorOf([&] {
                CheckDistortionMap(kitti, {-0.25, -0.15, 0, 0, 0});
              }),
              HasSubstr("invalid option camera.k1: -0.25 folds"));
  // A fold and a pole: no single coefficient is at fault, so all are named.
  EXPECT_THAT(ErrorOf([&] {
                CheckDistortionMap(kitti, {-1, 0, 0, 0, 0, -1.5, 0, 0});
              }),
              HasSubstr("invalid option camera.k1/k2/p1/p2/k3/k4/k5/k6: "));
}

}  // namespace
}  // namespace roadscale
