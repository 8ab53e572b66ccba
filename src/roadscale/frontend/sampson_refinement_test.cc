#include "roadscale/frontend/sampson_refinement.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/geometry/angles.h"
#include "roadscale/testing/frontend_test_util.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

struct Normalised {
  std::vector<Eigen::Vector2d> prev;
  std::vector<Eigen::Vector2d> cur;
};

Normalised Normalise(const testing::TwoViewScene& scene, const PinholeCamera& camera) {
  Normalised n;
  for (const Correspondence& c : scene.correspondences) {
    n.prev.push_back(camera.Unproject(c.prev).head<2>());
    n.cur.push_back(camera.Unproject(c.cur).head<2>());
  }
  return n;
}

TEST(SampsonRefinement, ConvergesToTheTruthFromAPerturbedStart) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Eigen::Matrix3d R = testing::RotationFromDegrees(2.0, 0.5, -0.3);
  const Eigen::Vector3d t = (-R * Eigen::Vector3d(0.1, 0.02, 1.0)).normalized();
  const Normalised data =
      Normalise(testing::MakeTwoViewScene(camera, R, t, 300, /*noise_px=*/0.0), camera);

  const Eigen::Matrix3d R0 = testing::RotationFromDegrees(0.4, -0.3, 0.2) * R;
  const Eigen::Vector3d t0 = (t + Eigen::Vector3d(0.03, -0.02, 0.0)).normalized();
  const SampsonRefinementResult result =
      RefineRelativePoseSampson(R0, t0, data.prev, data.cur, camera.fx, {});
  EXPECT_GT(result.initial_rms_px, 1.0);
  EXPECT_LT(result.final_rms_px, 1e-6);
  EXPECT_LT(RotationAngle(result.rotation.transpose() * R) * kDegreesPerRadian, 1e-6);
  EXPECT_LT(std::acos(std::min(1.0, result.direction.dot(t))) * kDegreesPerRadian, 1e-5);
  EXPECT_NEAR(result.direction.norm(), 1.0, 1e-12);
  EXPECT_GT(result.iterations, 0);
}

TEST(SampsonRefinement, SampsonErrorIsTheDistanceToTheEpipolarLine) {
  // Pure sideways motion: epipolar lines are horizontal; a vertical offset of d pixels in the
  // current image is a Sampson error of d / sqrt(2) (shared between both images).
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d t = Eigen::Vector3d::UnitX();
  Eigen::Matrix3d skew;
  skew << 0, -t.z(), t.y(), t.z(), 0, -t.x(), -t.y(), t.x(), 0;
  const double f = 500.0;
  const Eigen::Vector2d prev(0.1, 0.05);
  const Eigen::Vector2d cur(0.3, 0.05 + 2.0 / f);
  EXPECT_NEAR(std::abs(SampsonErrorPx(skew * R, prev, cur, f)), 2.0 / std::sqrt(2.0), 1e-9);
}

TEST(SampsonRefinement, RejectsBadInput) {
  SampsonRefinementOptions options;
  options.loss_scale_px = 0.0;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_THROW(RefineRelativePoseSampson(Eigen::Matrix3d::Identity(), Eigen::Vector3d::UnitZ(),
                                         {{0.0, 0.0}}, {}, 700.0, {}),
               Error);
  EXPECT_THROW(RefineRelativePoseSampson(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), {},
                                         {}, 700.0, {}),
               Error);
}

}  // namespace
}  // namespace roadscale
