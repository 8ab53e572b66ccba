#include "roadscale/scale/road_homography_refit.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/geometry/angles.h"
#include "roadscale/testing/synthetic_road_scene.h"
#include "roadscale/util/random.h"

#include <Eigen/Geometry>

namespace roadscale {
namespace {

struct RoadTracks {
  std::vector<Eigen::Vector2d> prev;
  std::vector<Eigen::Vector2d> cur;
  std::vector<int> indices;
};

// Road points 5-20 m ahead and up to 4 m to the side, seen before and after `motion`
// (metric), with Gaussian pixel noise on the current pixels.
RoadTracks Track(const Plane& road, const Rigid3d& motion, double noise_px, uint32_t seed) {
  const PinholeCamera camera = KittiOdometryCamera();
  Rng rng(seed);
  RoadTracks tracks;
  for (const Eigen::Vector3d& point :
       testing::PointsOnPlane(road, 150, -4.0, 4.0, 5.0, 20.0, seed)) {
    const Eigen::Vector3d moved = motion * point;
    if (moved.z() <= 0.0) continue;
    const Eigen::Vector2d prev = camera.Project(point);
    // One draw a statement: argument order is the compiler's.
    const double dy = noise_px * rng.Normal();
    const Eigen::Vector2d cur =
        camera.Project(moved) + Eigen::Vector2d(noise_px * rng.Normal(), dy);
    if (!camera.IsInside(prev) || !camera.IsInside(cur)) continue;
    tracks.indices.push_back(static_cast<int>(tracks.prev.size()));
    tracks.prev.push_back(prev);
    tracks.cur.push_back(cur);
  }
  return tracks;
}

// The motion with its translation scaled to unit length (what the scale stage is given).
Rigid3d UnitBaseline(const Rigid3d& motion) {
  return MakeRigid3d(motion.linear(), motion.translation().normalized());
}

TEST(RoadHomographyRefit, ExactTracksGiveTheExactPlaneFromAWrongStart) {
  const double pitch = 1.5 * kRadiansPerDegree;
  const Plane road{Eigen::Vector3d(0.02, std::cos(pitch), std::sin(pitch)).normalized(), 1.65};
  const double step = 1.1;
  const Rigid3d motion = testing::DriveAlongRoad(road, step, 1.0 * kRadiansPerDegree);
  const RoadTracks tracks = Track(road, motion, 0.0, 3);
  ASSERT_GT(tracks.indices.size(), 100u);
  const Plane start{Eigen::Vector3d(0.0, 1.0, 0.03).normalized(), 1.4 / step};
  for (const bool rotation : {false, true}) {
    for (const bool tangent : {false, true}) {
      RoadHomographyRefitOptions options;
      options.refine_rotation = rotation;
      options.tangent_to_travel = tangent;
      const std::optional<RoadHomographyRefit> refit =
          RefitRoadHomography(tracks.prev, tracks.cur, tracks.indices, UnitBaseline(motion),
                              KittiOdometryCamera(), start, options);
      ASSERT_TRUE(refit) << rotation << tangent;
      // Heights in units of the baseline: the metric height over the step.
      EXPECT_NEAR(refit->plane.height * step, 1.65, 1e-6) << rotation << tangent;
      EXPECT_LT(AngleBetween(refit->plane.normal, road.normal), 1e-6) << rotation << tangent;
      EXPECT_LT(refit->rotation_change_rad, 1e-8);
      EXPECT_LT(refit->rms_px, 1e-6);
    }
  }
}

TEST(RoadHomographyRefit, TransferMatchesTheProjectionOfThePlanePoint) {
  const Plane road{Eigen::Vector3d(0.0, 0.999, 0.02).normalized(), 1.5};
  const Rigid3d motion = testing::DriveAlongRoad(road, 0.9, 2.0 * kRadiansPerDegree);
  // The road point 1 m right of and 9 m ahead of the camera.
  const Eigen::Vector3d above(1.0, 0.0, 9.0);
  const Eigen::Vector3d point =
      above + (road.height - road.normal.dot(above)) / road.normal.y() * Eigen::Vector3d::UnitY();
  ASSERT_NEAR(road.SignedDistance(point), 0.0, 1e-12);
  const PinholeCamera camera = KittiOdometryCamera();
  const std::optional<Eigen::Vector2d> transferred =
      TransferThroughRoadPlane(camera.Project(point), motion.linear(), motion.translation(),
                               road.normal / road.height, camera);
  ASSERT_TRUE(transferred);
  EXPECT_LT((*transferred - camera.Project(motion * point)).norm(), 1e-9);
}

// The frontend's rotation 0.05 deg off in pitch (the size of its errors at KITTI speeds):
// every road point moves by 0.6 px, which the plane alone cannot absorb; refining the
// rotation with the plane recovers the height.
TEST(RoadHomographyRefit, RefiningTheRotationRemovesAPitchErrorOfTheMotion) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const double step = 1.0;
  const Rigid3d motion = testing::DriveAlongRoad(road, step, 0.5 * kRadiansPerDegree);
  const Eigen::Matrix3d pitch_error =
      Eigen::AngleAxisd(0.05 * kRadiansPerDegree, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Rigid3d given = MakeRigid3d(pitch_error * motion.linear(), motion.translation());
  double rotation_fixed_error = 0.0;
  for (uint32_t seed : {1U, 2U, 3U, 4U}) {
    const RoadTracks tracks = Track(road, motion, 0.2, seed);
    RoadHomographyRefitOptions options;
    options.refine_rotation = true;
    const std::optional<RoadHomographyRefit> refit =
        RefitRoadHomography(tracks.prev, tracks.cur, tracks.indices, UnitBaseline(given),
                            KittiOdometryCamera(), road, options);
    ASSERT_TRUE(refit);
    EXPECT_LT(std::abs(refit->plane.height * step / 1.65 - 1.0), 0.005) << "seed " << seed;
    EXPECT_NEAR(refit->rotation_change_rad, 0.05 * kRadiansPerDegree, 0.01 * kRadiansPerDegree)
        << "seed " << seed;

    options.refine_rotation = false;
    const std::optional<RoadHomographyRefit> fixed =
        RefitRoadHomography(tracks.prev, tracks.cur, tracks.indices, UnitBaseline(given),
                            KittiOdometryCamera(), road, options);
    ASSERT_TRUE(fixed);
    rotation_fixed_error += std::abs(fixed->plane.height * step / 1.65 - 1.0) / 4.0;
  }
  EXPECT_GT(rotation_fixed_error, 0.02);
}

// The road ahead rises by 0.6 deg more than the car's own motion (a grade that changes):
// holding the normal perpendicular to the travel biases the height, the free normal does
// not, and the prior's pull sits in between, near the free fit (measured: 5.5 %, 0, 0.8 %).
TEST(RoadHomographyRefit, ATravelPriorFollowsARoadThatBendsAwayFromTheCarsPlane) {
  const Plane flat{Eigen::Vector3d::UnitY(), 1.65};
  const Rigid3d motion = testing::DriveAlongRoad(flat, 1.0, 0.0);
  const double bend = 0.6 * kRadiansPerDegree;
  const Plane ahead{Eigen::Vector3d(0.0, std::cos(bend), std::sin(bend)), 1.65};
  const RoadTracks tracks = Track(ahead, motion, 0.0, 9);
  const auto height_error = [&](bool tangent, double prior) {
    RoadHomographyRefitOptions options;
    options.tangent_to_travel = tangent;
    options.travel_prior_px_per_deg = prior;
    const std::optional<RoadHomographyRefit> refit = RefitRoadHomography(
        tracks.prev, tracks.cur, tracks.indices, motion, KittiOdometryCamera(), flat, options);
    EXPECT_TRUE(refit);
    return refit ? std::abs(refit->plane.height / 1.65 - 1.0) : 1.0;
  };
  const double hard = height_error(true, 0.0);
  const double free = height_error(false, 0.0);
  const double pulled = height_error(false, 3.0);
  EXPECT_GT(hard, 0.05);
  EXPECT_LT(free, 1e-6);
  EXPECT_LT(pulled, hard / 3.0);
  EXPECT_GT(pulled, 0.002);  // the pull is felt: not the free fit
}

TEST(RoadHomographyRefit, RefusesTooFewTracksAndAPlaneBehindTheCamera) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, 0.0);
  const RoadTracks tracks = Track(road, motion, 0.0, 5);
  const std::vector<int> five(tracks.indices.begin(), tracks.indices.begin() + 5);
  EXPECT_FALSE(
      RefitRoadHomography(tracks.prev, tracks.cur, five, motion, KittiOdometryCamera(), road, {}));
  EXPECT_FALSE(RefitRoadHomography(tracks.prev, tracks.cur, tracks.indices, motion,
                                   KittiOdometryCamera(), Plane{road.normal, -1.0}, {}));
  RoadHomographyRefitOptions bad;
  bad.loss_scale_px = 0.0;
  EXPECT_ANY_THROW(RefitRoadHomography(tracks.prev, tracks.cur, tracks.indices, motion,
                                       KittiOdometryCamera(), road, bad));
  bad = RoadHomographyRefitOptions();
  bad.travel_prior_px_per_deg = -1.0;
  EXPECT_ANY_THROW(RefitRoadHomography(tracks.prev, tracks.cur, tracks.indices, motion,
                                       KittiOdometryCamera(), road, bad));
}

}  // namespace
}  // namespace roadscale
