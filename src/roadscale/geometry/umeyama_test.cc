#include "roadscale/geometry/umeyama.h"

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

#include <Eigen/Geometry>

namespace roadscale {
namespace {

// A fixed, scattered, non-planar point set (no random generator: the test must not depend
// on a library's distribution implementation).
Eigen::Matrix3Xd ExamplePoints() {
  Eigen::Matrix3Xd points(3, 7);
  points << 0.0, 1.0, -2.0, 3.5, 0.3, -1.2, 4.0,  //
      0.0, 0.5, 1.5, -0.7, 2.2, -3.0, 1.1,        //
      0.0, 2.0, 0.4, 1.3, -1.8, 0.9, 5.0;
  return points;
}

Eigen::Matrix3d ExampleRotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -1.0, 0.4).normalized()).toRotationMatrix();
}

Eigen::Matrix3Xd Apply(const Similarity3d& transform, const Eigen::Matrix3Xd& points) {
  Eigen::Matrix3Xd result(3, points.cols());
  for (Eigen::Index i = 0; i < points.cols(); ++i) result.col(i) = transform(points.col(i));
  return result;
}

double Cost(const Similarity3d& transform, const Eigen::Matrix3Xd& src,
            const Eigen::Matrix3Xd& dst) {
  return (Apply(transform, src) - dst).squaredNorm();
}

TEST(Umeyama, RecoversAKnownSimilarity) {
  Similarity3d truth;
  truth.rotation = ExampleRotation();
  truth.translation = Eigen::Vector3d(4.0, -2.0, 10.0);
  truth.scale = 0.8;
  const Eigen::Matrix3Xd src = ExamplePoints();
  const Similarity3d fitted = UmeyamaAlignment(src, Apply(truth, src), /*with_scale=*/true);
  EXPECT_NEAR(fitted.scale, 0.8, 1e-12);
  EXPECT_TRUE(fitted.rotation.isApprox(truth.rotation, 1e-12));
  EXPECT_TRUE(fitted.translation.isApprox(truth.translation, 1e-12));
}

TEST(Umeyama, RigidFitKeepsUnitScaleAndFindsTheRotation) {
  Similarity3d truth;
  truth.rotation = ExampleRotation();
  truth.translation = Eigen::Vector3d(-1.0, 0.5, 2.0);
  const Eigen::Matrix3Xd src = ExamplePoints();
  const Similarity3d fitted = UmeyamaAlignment(src, Apply(truth, src), /*with_scale=*/false);
  EXPECT_EQ(fitted.scale, 1.0);
  EXPECT_TRUE(fitted.rotation.isApprox(truth.rotation, 1e-12));
  EXPECT_TRUE(fitted.translation.isApprox(truth.translation, 1e-12));

  // The optimal rotation does not depend on the scale between the sets; the translation
  // still maps the source centroid to the destination centroid.
  truth.scale = 2.0;
  const Eigen::Matrix3Xd dst = Apply(truth, src);
  const Similarity3d rigid = UmeyamaAlignment(src, dst, /*with_scale=*/false);
  EXPECT_TRUE(rigid.rotation.isApprox(truth.rotation, 1e-12));
  EXPECT_TRUE(rigid(src.rowwise().mean()).isApprox(dst.rowwise().mean(), 1e-12));
}

TEST(Umeyama, NeverReturnsAReflection) {
  // dst is the mirror image of src: the best orthogonal matrix is a reflection, which the
  // sign correction must turn into the best proper rotation.
  const Eigen::Matrix3Xd src = ExamplePoints();
  Eigen::Matrix3Xd dst = src;
  dst.row(0) *= -1.0;
  for (bool with_scale : {false, true}) {
    const Similarity3d fitted = UmeyamaAlignment(src, dst, with_scale);
    EXPECT_NEAR(fitted.rotation.determinant(), 1.0, 1e-12);
    EXPECT_TRUE((fitted.rotation.transpose() * fitted.rotation).isIdentity(1e-12));
    EXPECT_GT(fitted.scale, 0.0);
  }
}

TEST(Umeyama, PlanarPointsAreRecoveredExactly) {
  // Points on a plane give a rank-2 covariance, the paper's second case for S.
  Eigen::Matrix3Xd src(3, 5);
  src << 0, 1, 0, 2, -1,  //
      0, 0, 1, 3, 2,      //
      0, 0, 0, 0, 0;
  Similarity3d truth;
  truth.rotation = ExampleRotation();
  truth.translation = Eigen::Vector3d(0.0, 1.0, -3.0);
  truth.scale = 1.7;
  const Similarity3d fitted = UmeyamaAlignment(src, Apply(truth, src), /*with_scale=*/true);
  EXPECT_NEAR(fitted.scale, 1.7, 1e-12);
  EXPECT_TRUE(fitted.rotation.isApprox(truth.rotation, 1e-12));
  EXPECT_TRUE(fitted.translation.isApprox(truth.translation, 1e-12));
}

TEST(Umeyama, NoisyFitIsALocalMinimumOfTheCost) {
  const Eigen::Matrix3Xd src = ExamplePoints();
  Similarity3d truth;
  truth.rotation = ExampleRotation();
  truth.translation = Eigen::Vector3d(1.0, 2.0, 3.0);
  truth.scale = 1.3;
  Eigen::Matrix3Xd dst = Apply(truth, src);
  Eigen::Matrix3Xd noise(3, 7);
  noise << 0.1, -0.2, 0.05, 0.0, 0.3, -0.1, 0.2,  //
      -0.3, 0.1, 0.2, -0.05, 0.0, 0.15, -0.1,     //
      0.2, 0.0, -0.25, 0.1, -0.1, 0.05, 0.3;
  dst += noise;
  const Similarity3d fitted = UmeyamaAlignment(src, dst, /*with_scale=*/true);
  const double best = Cost(fitted, src, dst);
  for (int axis = 0; axis < 3; ++axis) {
    for (double step : {-1e-4, 1e-4}) {
      Similarity3d moved = fitted;
      moved.rotation =
          Eigen::AngleAxisd(step, Eigen::Vector3d::Unit(axis)).toRotationMatrix() * moved.rotation;
      EXPECT_GT(Cost(moved, src, dst), best);
      moved = fitted;
      moved.translation(axis) += step;
      EXPECT_GT(Cost(moved, src, dst), best);
    }
  }
  for (double factor : {0.999, 1.001}) {
    Similarity3d moved = fitted;
    moved.scale *= factor;
    EXPECT_GT(Cost(moved, src, dst), best);
  }
}

TEST(Umeyama, SinglePointRigidFitIsATranslation) {
  const Eigen::Matrix3Xd src = Eigen::Vector3d(1.0, 2.0, 3.0);
  const Eigen::Matrix3Xd dst = Eigen::Vector3d(-1.0, 0.0, 5.0);
  const Similarity3d fitted = UmeyamaAlignment(src, dst, /*with_scale=*/false);
  EXPECT_TRUE(fitted(src.col(0)).isApprox(dst.col(0), 1e-15));
}

TEST(Umeyama, RejectsDegenerateInput) {
  const Eigen::Matrix3Xd src = ExamplePoints();
  EXPECT_THROW(UmeyamaAlignment(src, src.leftCols(3), true), Error);
  EXPECT_THROW(UmeyamaAlignment(Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xd(3, 0), false), Error);
  const Eigen::Matrix3Xd same = Eigen::Vector3d(1.0, 1.0, 1.0).replicate(1, 4);
  EXPECT_THROW(UmeyamaAlignment(same, src.leftCols(4), /*with_scale=*/true), Error);
  EXPECT_NO_THROW(UmeyamaAlignment(same, src.leftCols(4), /*with_scale=*/false));
}

}  // namespace
}  // namespace roadscale
