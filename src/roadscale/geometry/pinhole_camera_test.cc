#include "roadscale/geometry/pinhole_camera.h"

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(PinholeCamera, ProjectUnprojectRoundTrip) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Eigen::Vector3d point(1.5, 1.65, 12.0);
  const Eigen::Vector2d pixel = camera.Project(point);
  EXPECT_NEAR(pixel.x(), 718.856 * 1.5 / 12.0 + 607.1928, 1e-12);
  EXPECT_NEAR(pixel.y(), 718.856 * 1.65 / 12.0 + 185.2157, 1e-12);
  const Eigen::Vector3d ray = camera.Unproject(pixel);
  EXPECT_TRUE(ray.isApprox(point / point.z(), 1e-12));
  EXPECT_TRUE((camera.K() * ray).isApprox(Eigen::Vector3d(pixel.x(), pixel.y(), 1.0), 1e-12));
}

TEST(PinholeCamera, InsideUsesPixelCentres) {
  const PinholeCamera camera = KittiOdometryCamera();
  EXPECT_TRUE(camera.IsInside({0.0, 0.0}));
  EXPECT_TRUE(camera.IsInside({1240.4, 375.4}));
  EXPECT_FALSE(camera.IsInside({1240.6, 10.0}));
  EXPECT_FALSE(camera.IsInside({10.0, -0.6}));
}

TEST(PinholeCamera, CheckRejectsBadIntrinsics) {
  PinholeCamera camera = KittiOdometryCamera();
  EXPECT_NO_THROW(camera.Check());
  camera.fx = 0.0;
  EXPECT_THROW(camera.Check(), Error);
  camera = KittiOdometryCamera();
  camera.width = 0;
  EXPECT_THROW(camera.Check(), Error);
}

}  // namespace
}  // namespace roadscale
