#include "roadscale/scale/inverse_depth_plane.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "roadscale/scale/road_plane_ransac.h"
#include "roadscale/scale/synthetic_road_scene.h"

namespace roadscale {
namespace {

constexpr double kDeg = M_PI / 180.0;

std::vector<int> AllIndices(size_t count) {
  std::vector<int> indices(count);
  for (size_t i = 0; i < count; ++i) indices[i] = static_cast<int>(i);
  return indices;
}

TEST(InverseDepthPlane, ExactPointsGiveTheExactPlane) {
  const double pitch = 2.0 * kDeg;
  const Plane road{Eigen::Vector3d(0.03, std::cos(pitch), std::sin(pitch)).normalized(), 1.3};
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, 1.0 * kDeg);
  const std::vector<Eigen::Vector3d> points =
      testing::PointsOnPlane(road, 200, -5.0, 5.0, 5.0, 25.0, 7);
  for (bool weighted : {false, true}) {
    const std::optional<Plane> plane =
        FitPlaneInverseDepth(points, AllIndices(points.size()), motion, road.normal, weighted);
    ASSERT_TRUE(plane);
    EXPECT_NEAR(plane->height, 1.3, 1e-9);
    EXPECT_LT(AngleBetween(plane->normal, road.normal), 1e-9);
  }
}

TEST(InverseDepthPlane, NoiseAlongTheRaysTiltsTotalLeastSquaresButNotTheInverseDepthFit) {
  // Road points 6-14 m ahead with 3 % of Gaussian noise on their inverse depth, i.e. moved
  // along their rays (what triangulation does). The total-least-squares plane falls away
  // ahead and comes too near the camera; the inverse-depth fit stays within its noise.
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, 0.0);
  std::vector<Eigen::Vector3d> points =
      testing::PointsOnPlane(road, 20000, -3.0, 3.0, 6.0, 14.0, 3);
  std::mt19937 generator(11);
  std::normal_distribution<double> noise(0.0, 0.03);
  for (Eigen::Vector3d& point : points) point /= 1.0 + noise(generator);
  const std::vector<int> all = AllIndices(points.size());
  const std::optional<Plane> tls = FitPlaneLeastSquares(points, all, road.normal);
  ASSERT_TRUE(tls);
  EXPECT_LT(tls->PitchRad(), -0.1 * kDeg);
  EXPECT_LT(tls->height, 1.65 * 0.99);
  for (bool weighted : {false, true}) {
    const std::optional<Plane> plane =
        FitPlaneInverseDepth(points, all, motion, road.normal, weighted);
    ASSERT_TRUE(plane);
    EXPECT_NEAR(plane->height, 1.65, 1.65 * 0.002) << "weighted " << weighted;
    EXPECT_LT(std::abs(plane->PitchRad()), 0.02 * kDeg) << "weighted " << weighted;
  }
}

TEST(InverseDepthPlane, SensitivityIsTheImageShiftPerUnitOfInverseDepth) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, 0.5 * kDeg);
  const Eigen::Vector3d ray(0.2, 0.15, 1.0);
  const double rho = 0.1;
  const auto image = [&](double r) {
    const Eigen::Vector3d in_cur = motion * Eigen::Vector3d(ray / r);
    return Eigen::Vector2d(in_cur.head<2>() / in_cur.z());
  };
  const double step = 1e-6;
  const double numeric = (image(rho + step) - image(rho - step)).norm() / (2 * step);
  EXPECT_NEAR(InverseDepthSensitivity(ray, rho, motion), numeric, 1e-6 * numeric);
  // Straight ahead (at the epipole) the point does not move with its depth.
  EXPECT_NEAR(InverseDepthSensitivity(Eigen::Vector3d(0, 0, 1), rho,
                                      testing::DriveAlongRoad(road, 1.0, 0.0)),
              0.0, 1e-12);
}

TEST(InverseDepthPlane, DegenerateInputGivesNoPlane) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, 0.0);
  const std::vector<Eigen::Vector3d> collinear = {
      {0, 1.65, 5}, {0, 1.65, 10}, {0, 1.65, 15}, {0, 1.65, 20}};
  EXPECT_FALSE(FitPlaneInverseDepth(collinear, AllIndices(4), motion, road.normal, true));
  EXPECT_FALSE(FitPlaneInverseDepth(collinear, {0, 1}, motion, road.normal, true));
  // A plane above the camera (h < 0 for the reference normal) is not a road.
  const std::vector<Eigen::Vector3d> ceiling = {{-2, -3, 5}, {2, -3, 6}, {0, -3, 9}, {1, -3, 12}};
  EXPECT_FALSE(FitPlaneInverseDepth(ceiling, AllIndices(4), motion, road.normal, false));
}

}  // namespace
}  // namespace roadscale
