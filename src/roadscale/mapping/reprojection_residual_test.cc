#include "roadscale/mapping/reprojection_residual.h"

#include <memory>

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>

#include <gtest/gtest.h>

#include "roadscale/util/random.h"

namespace roadscale {
namespace {

// The reprojection error as it was written for Ceres' automatic derivatives: the reference
// the analytic Jacobians are checked against.
struct AutoDiffReprojection {
  double fx, fy, cx, cy;
  Eigen::Vector2d observed;

  template <typename T>
  bool operator()(const T* cam_from_world, const T* point_world, T* residual) const {
    T point_cam[3];
    ceres::AngleAxisRotatePoint(cam_from_world, point_world, point_cam);
    for (int i = 0; i < 3; ++i) point_cam[i] += cam_from_world[3 + i];
    if (point_cam[2] < T(1e-6)) return false;
    residual[0] = T(fx) * point_cam[0] / point_cam[2] + T(cx) - T(observed.x());
    residual[1] = T(fy) * point_cam[1] / point_cam[2] + T(cy) - T(observed.y());
    return true;
  }
};

struct Evaluation {
  bool ok = false;
  double residual[2] = {0.0, 0.0};
  double pose_jacobian[12] = {};
  double point_jacobian[6] = {};
};

Evaluation Evaluate(const ceres::CostFunction& cost, const double* pose, const double* point) {
  Evaluation e;
  const double* parameters[2] = {pose, point};
  double* jacobians[2] = {e.pose_jacobian, e.point_jacobian};
  e.ok = cost.Evaluate(parameters, e.residual, jacobians);
  return e;
}

// |a - b| <= 1e-8 max(|b|, the block's largest entry): relative to the entry, except that an
// entry near zero is judged against the scale of its Jacobian.
void ExpectNear(const double* a, const double* b, int n) {
  double scale = 0.0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(b[i]));
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(a[i], b[i], 1e-8 * std::max(std::abs(b[i]), scale)) << "entry " << i;
  }
}

// A random pose (any rotation angle up to pi, translation up to 5 m) and a point 2-60 m in
// front of it, observed near its projection.
struct RandomCase {
  double pose[6];
  double point[3];
  Eigen::Vector2d observed;
};

RandomCase MakeCase(Rng* rng, double max_angle) {
  // One draw a statement: the order of a call's arguments is the compiler's, and the cases
  // must be the same with every compiler.
  const auto unit = [rng] { return rng->Uniform(-1.0, 1.0); };
  RandomCase c;
  Eigen::Vector3d axis;
  for (int i = 0; i < 3; ++i) axis[i] = unit();
  axis.normalize();
  const double angle = max_angle * std::abs(unit());
  for (int i = 0; i < 3; ++i) c.pose[i] = axis[i] * angle;
  for (int i = 0; i < 3; ++i) c.pose[3 + i] = 5.0 * unit();
  // The point in the camera, then moved to the world: x = R^T (x_cam - t).
  const double x_cam = 20.0 * unit();
  const double y_cam = 5.0 * unit();
  const Eigen::Vector3d point_cam(x_cam, y_cam, 31.0 + 29.0 * unit());
  double shifted[3];
  for (int i = 0; i < 3; ++i) shifted[i] = point_cam[i] - c.pose[3 + i];
  const double inverse_rotation[3] = {-c.pose[0], -c.pose[1], -c.pose[2]};
  ceres::AngleAxisRotatePoint(inverse_rotation, shifted, c.point);
  const double u = 600.0 + 400.0 * unit();
  c.observed = Eigen::Vector2d(u, 190.0 + 150.0 * unit());
  return c;
}

void CompareWithAutoDiff(const RandomCase& c) {
  const PinholeCamera camera = KittiOdometryCamera();
  const std::unique_ptr<ceres::CostFunction> analytic(
      ReprojectionResidual::Create(camera, c.observed));
  const ceres::AutoDiffCostFunction<AutoDiffReprojection, 2, 6, 3> automatic(
      new AutoDiffReprojection{camera.fx, camera.fy, camera.cx, camera.cy, c.observed});
  const Evaluation a = Evaluate(*analytic, c.pose, c.point);
  const Evaluation b = Evaluate(automatic, c.pose, c.point);
  ASSERT_TRUE(a.ok);
  ASSERT_TRUE(b.ok);
  // The same operations give the same residual, bit for bit.
  EXPECT_EQ(a.residual[0], b.residual[0]);
  EXPECT_EQ(a.residual[1], b.residual[1]);
  ExpectNear(a.pose_jacobian, b.pose_jacobian, 12);
  ExpectNear(a.point_jacobian, b.point_jacobian, 6);

  // The pose-only form: the same residual and pose Jacobian for the fixed point.
  const std::unique_ptr<ceres::CostFunction> pose_only(PoseOnlyReprojectionResidual::Create(
      camera, c.observed, Eigen::Vector3d(c.point[0], c.point[1], c.point[2])));
  const double* parameters[1] = {c.pose};
  double residual[2];
  double jacobian[12];
  double* jacobians[1] = {jacobian};
  ASSERT_TRUE(pose_only->Evaluate(parameters, residual, jacobians));
  EXPECT_EQ(residual[0], a.residual[0]);
  EXPECT_EQ(residual[1], a.residual[1]);
  ExpectNear(jacobian, b.pose_jacobian, 12);
}

TEST(ReprojectionResidual, JacobiansEqualAutomaticDerivativesOnRandomPoses) {
  Rng rng(13);
  for (int i = 0; i < 2000; ++i) CompareWithAutoDiff(MakeCase(&rng, M_PI));
}

TEST(ReprojectionResidual, JacobiansEqualAutomaticDerivativesAtSmallAngles) {
  // Keyframe rotations in a window are small; 1e-9 rad is inside Ceres' first-order branch.
  Rng rng(7);
  for (const double max_angle : {1e-2, 1e-4, 1e-6, 1e-9, 0.0}) {
    for (int i = 0; i < 200; ++i) CompareWithAutoDiff(MakeCase(&rng, max_angle));
  }
}

TEST(ReprojectionResidual, FailsForAPointBehindTheCamera) {
  const std::unique_ptr<ceres::CostFunction> cost(
      ReprojectionResidual::Create(KittiOdometryCamera(), Eigen::Vector2d(600.0, 180.0)));
  const double pose[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double point[3] = {1.0, 0.5, -4.0};
  EXPECT_FALSE(Evaluate(*cost, pose, point).ok);
}

TEST(ReprojectionResidual, EvaluatesWithoutJacobiansOrWithOnlyOne) {
  Rng rng(3);
  const RandomCase c = MakeCase(&rng, 0.5);
  const std::unique_ptr<ceres::CostFunction> cost(
      ReprojectionResidual::Create(KittiOdometryCamera(), c.observed));
  const Evaluation full = Evaluate(*cost, c.pose, c.point);
  const double* parameters[2] = {c.pose, c.point};
  double residual[2];
  ASSERT_TRUE(cost->Evaluate(parameters, residual, nullptr));
  EXPECT_EQ(residual[0], full.residual[0]);
  double point_jacobian[6];
  double* only_point[2] = {nullptr, point_jacobian};
  ASSERT_TRUE(cost->Evaluate(parameters, residual, only_point));
  for (int i = 0; i < 6; ++i) EXPECT_EQ(point_jacobian[i], full.point_jacobian[i]);
}

}  // namespace
}  // namespace roadscale
