#include "roadscale/frontend/two_view_motion.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/frontend/sampson_refinement.h"
#include "roadscale/geometry/angles.h"
#include "roadscale/testing/frontend_test_util.h"
#include "roadscale/util/error.h"
#include "roadscale/util/random.h"

namespace roadscale {
namespace {

double RotationErrorDeg(const Eigen::Matrix3d& estimate, const Eigen::Matrix3d& truth) {
  return RotationAngle(estimate.transpose() * truth) * kDegreesPerRadian;
}

double DirectionErrorDeg(const Eigen::Vector3d& estimate, const Eigen::Vector3d& truth) {
  const double c = estimate.normalized().dot(truth.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0)) * kDegreesPerRadian;
}

// cur_from_prev translation of a camera whose centre moves by `centre_motion` (in the
// previous camera's frame) while rotating by R.
Eigen::Vector3d TranslationOf(const Eigen::Matrix3d& R, const Eigen::Vector3d& centre_motion) {
  return -R * centre_motion;
}

struct Case {
  const char* name;
  Eigen::Matrix3d R;
  Eigen::Vector3d centre_motion;
  // Bound on the median direction error at 0.05 px noise. Sideways motion (not a car's) is
  // the least precise: with KITTI's narrow vertical field of view a small pitch and a
  // vertical component of the translation explain the flow almost equally well (30 scenes:
  // median 0.033 deg, 90th percentile 0.13 deg, against 0.018 / 0.049 deg driving forward).
  double direction_bound_deg;
};

const Case kCases[] = {
    {"forward", testing::RotationFromDegrees(1.5, 0.3, -0.2), {0.02, 0.01, 1.0}, 0.05},
    {"forward turning", testing::RotationFromDegrees(-4.0, 0.5, 0.3), {-0.1, 0.02, 0.8}, 0.05},
    {"sideways", testing::RotationFromDegrees(0.5, -1.0, 0.0), {1.0, 0.05, 0.2}, 0.1},
};

double Median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// Errors are statistical: each case runs on several random scenes and the median is tested
// (one scene may be unlucky), with a looser bound on every scene.
constexpr int kScenes = 8;

TEST(TwoViewMotion, RecoversRotationAndDirectionWithPixelNoise) {
  const PinholeCamera camera = KittiOdometryCamera();
  for (const Case& c : kCases) {
    const Eigen::Vector3d t = TranslationOf(c.R, c.centre_motion);
    std::vector<double> rotation_errors;
    std::vector<double> direction_errors;
    for (int scene_seed = 1; scene_seed <= kScenes; ++scene_seed) {
      const testing::TwoViewScene scene =
          testing::MakeTwoViewScene(camera, c.R, t, 1000, /*noise_px=*/0.05, 0.0, scene_seed);
      const TwoViewMotion motion = EstimateTwoViewMotion(scene.correspondences, camera, {});
      ASSERT_EQ(motion.status, MotionStatus::kOk) << c.name;
      rotation_errors.push_back(RotationErrorDeg(motion.rotation, c.R));
      direction_errors.push_back(DirectionErrorDeg(motion.direction, t));
      EXPECT_LT(rotation_errors.back(), 0.05) << c.name << " scene " << scene_seed;
      EXPECT_LT(direction_errors.back(), 0.25) << c.name << " scene " << scene_seed;
      EXPECT_NEAR(motion.direction.norm(), 1.0, 1e-12);
      EXPECT_GT(motion.inlier_ratio, 0.95) << c.name;
      EXPECT_GT(motion.parallax_px, 1.0) << c.name;
      EXPECT_LT(motion.refined_sampson_rms_px, 0.1) << c.name;
    }
    EXPECT_LT(Median(rotation_errors), 0.05) << c.name;
    EXPECT_LT(Median(direction_errors), c.direction_bound_deg) << c.name;
  }
}

TEST(TwoViewMotion, RefinementReachesTheAccuracyOfTheFiveParameterOptimum) {
  // Without refinement the five-point model is off by a degree or more; with it the error is
  // that of the least-squares optimum started from the truth (the statistical limit).
  const PinholeCamera camera = KittiOdometryCamera();
  const Case& c = kCases[0];
  const Eigen::Vector3d t = TranslationOf(c.R, c.centre_motion);
  std::vector<double> refined;
  std::vector<double> unrefined;
  std::vector<double> optimum;
  TwoViewMotionOptions no_refinement;
  no_refinement.refine = false;
  for (int scene_seed = 1; scene_seed <= kScenes; ++scene_seed) {
    const testing::TwoViewScene scene =
        testing::MakeTwoViewScene(camera, c.R, t, 1000, /*noise_px=*/0.1, 0.0, scene_seed);
    refined.push_back(
        DirectionErrorDeg(EstimateTwoViewMotion(scene.correspondences, camera, {}).direction, t));
    unrefined.push_back(DirectionErrorDeg(
        EstimateTwoViewMotion(scene.correspondences, camera, no_refinement).direction, t));
    std::vector<Eigen::Vector2d> prev;
    std::vector<Eigen::Vector2d> cur;
    for (const Correspondence& k : scene.correspondences) {
      prev.push_back(camera.Unproject(k.prev).head<2>());
      cur.push_back(camera.Unproject(k.cur).head<2>());
    }
    SampsonRefinementOptions least_squares;
    least_squares.loss_scale_px = 1e6;
    optimum.push_back(DirectionErrorDeg(
        RefineRelativePoseSampson(c.R, t.normalized(), prev, cur, camera.fx, least_squares)
            .direction,
        t));
  }
  EXPECT_GT(Median(unrefined), 0.5);
  EXPECT_LT(Median(refined), 1.3 * Median(optimum));
}

TEST(TwoViewMotion, RejectsThirtyPercentOutliers) {
  const PinholeCamera camera = KittiOdometryCamera();
  for (const Case& c : kCases) {
    const Eigen::Vector3d t = TranslationOf(c.R, c.centre_motion);
    std::vector<double> rotation_errors;
    std::vector<double> direction_errors;
    for (int scene_seed = 1; scene_seed <= kScenes; ++scene_seed) {
      const testing::TwoViewScene scene =
          testing::MakeTwoViewScene(camera, c.R, t, 1000, 0.05, /*outlier_ratio=*/0.3, scene_seed);
      const TwoViewMotion motion = EstimateTwoViewMotion(scene.correspondences, camera, {});
      ASSERT_EQ(motion.status, MotionStatus::kOk);
      rotation_errors.push_back(RotationErrorDeg(motion.rotation, c.R));
      direction_errors.push_back(DirectionErrorDeg(motion.direction, t));

      std::vector<int64_t> inliers = motion.inlier_track_ids;
      std::sort(inliers.begin(), inliers.end());
      int outliers = 0;
      int outliers_kept = 0;
      int good = 0;
      int good_kept = 0;
      for (size_t i = 0; i < scene.correspondences.size(); ++i) {
        const bool kept =
            std::binary_search(inliers.begin(), inliers.end(), scene.correspondences[i].track_id);
        (scene.is_outlier[i] ? outliers : good) += 1;
        (scene.is_outlier[i] ? outliers_kept : good_kept) += kept;
      }
      ASSERT_GT(outliers, 250);
      // An outlier displaced along its epipolar line cannot be told apart: a few stay.
      EXPECT_LT(outliers_kept, 0.1 * outliers) << c.name;
      EXPECT_GT(good_kept, 0.98 * good) << c.name;
      EXPECT_NEAR(motion.inlier_ratio,
                  static_cast<double>(motion.num_inliers) / scene.is_outlier.size(), 1e-12);
    }
    EXPECT_LT(Median(rotation_errors), 0.05) << c.name;
    // Outliers near the epipole leave false minima that the refinement mostly, not always,
    // avoids (see TwoViewMotionOptions::refinement_epipole_exclusion_deg).
    EXPECT_LT(Median(direction_errors), 0.2) << c.name;
  }
}

TEST(TwoViewMotion, KeepsTheDirectionAndRotationRightAtATinyBaseline) {
  // Creeping forward 30 cm among points 4-60 m away: a median parallax of 1.5-2 px, just
  // above min_parallax_px. The cheirality vote must still tell t from -t, and the rotation
  // must not be the one twisted by 180 degrees about the baseline: both are checked on every
  // scene with bounds far from those 180 degrees. At this parallax the outliers near the epipole
  // pull one scene in 16 more than 5 degrees off (300 scenes: direction median 0.44 deg, at
  // most 12 deg; rotation at most 0.11 deg), so accuracy is checked on the median.
  const PinholeCamera camera = KittiOdometryCamera();
  const Eigen::Matrix3d R = testing::RotationFromDegrees(0.05, 0.02, 0.0);
  const Eigen::Vector3d t = TranslationOf(R, {0.0, 0.0, 0.3});
  std::vector<double> rotation_errors;
  std::vector<double> direction_errors;
  for (int scene_seed = 1; scene_seed <= kScenes; ++scene_seed) {
    const testing::TwoViewScene scene =
        testing::MakeTwoViewScene(camera, R, t, 600, /*noise_px=*/0.1, 0.05, scene_seed);
    const TwoViewMotion motion = EstimateTwoViewMotion(scene.correspondences, camera, {});
    if (motion.status != MotionStatus::kOk) continue;
    rotation_errors.push_back(RotationErrorDeg(motion.rotation, R));
    direction_errors.push_back(DirectionErrorDeg(motion.direction, t));
    EXPECT_LT(rotation_errors.back(), 0.5) << "scene " << scene_seed;
    EXPECT_LT(direction_errors.back(), 20.0) << "scene " << scene_seed;
  }
  ASSERT_EQ(direction_errors.size(), static_cast<size_t>(kScenes));
  // The median of 8 scenes in 37 such groups: at most 0.027 deg and 2.5 deg.
  EXPECT_LT(Median(rotation_errors), 0.05);
  EXPECT_LT(Median(direction_errors), 3.0);
}

TEST(TwoViewMotion, ReportsAStationaryCamera) {
  const PinholeCamera camera = KittiOdometryCamera();
  const testing::TwoViewScene scene = testing::MakeTwoViewScene(camera, Eigen::Matrix3d::Identity(),
                                                                Eigen::Vector3d::Zero(), 500, 0.2);
  const TwoViewMotion motion = EstimateTwoViewMotion(scene.correspondences, camera, {});
  EXPECT_EQ(motion.status, MotionStatus::kStationary);
  EXPECT_TRUE(motion.rotation.isIdentity());
  EXPECT_EQ(motion.direction, Eigen::Vector3d::Zero());
  EXPECT_LT(motion.flow_px, 0.5);
}

TEST(TwoViewMotion, ReportsAPureRotationWithItsRotation) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Eigen::Matrix3d R = testing::RotationFromDegrees(3.0, 0.6, -0.3);
  const testing::TwoViewScene scene =
      testing::MakeTwoViewScene(camera, R, Eigen::Vector3d::Zero(), 500, 0.3, 0.2);
  const TwoViewMotion motion = EstimateTwoViewMotion(scene.correspondences, camera, {});
  EXPECT_EQ(motion.status, MotionStatus::kPureRotation);
  EXPECT_LT(RotationErrorDeg(motion.rotation, R), 0.05);
  EXPECT_EQ(motion.direction, Eigen::Vector3d::Zero());
  EXPECT_GT(motion.flow_px, 20.0);
  EXPECT_LT(motion.parallax_px, 1.0);
}

TEST(TwoViewMotion, ReportsTooFewTracksAndTooFewInliers) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Eigen::Matrix3d R = testing::RotationFromDegrees(1.0, 0.0, 0.0);
  const Eigen::Vector3d t = TranslationOf(R, {0.0, 0.0, 1.0});
  const testing::TwoViewScene few = testing::MakeTwoViewScene(camera, R, t, 20, 0.3);
  EXPECT_EQ(EstimateTwoViewMotion(few.correspondences, camera, {}).status,
            MotionStatus::kTooFewTracks);

  // Correspondences with no geometry at all: random pixel pairs.
  Rng rng(5);
  const auto pixel = [&] {
    const double x = rng.Uniform(0.0, camera.width - 1.0);
    return Eigen::Vector2d(x, rng.Uniform(0.0, camera.height - 1.0));
  };
  std::vector<Correspondence> junk(300);
  for (size_t i = 0; i < junk.size(); ++i) {
    junk[i].track_id = static_cast<int64_t>(i);
    junk[i].prev = pixel();
    junk[i].cur = pixel();
  }
  const TwoViewMotion motion = EstimateTwoViewMotion(junk, camera, {});
  EXPECT_EQ(motion.status, MotionStatus::kTooFewInliers);
  EXPECT_LT(motion.inlier_ratio, 0.3);
}

TEST(TwoViewMotion, IsDeterministic) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Eigen::Matrix3d R = testing::RotationFromDegrees(1.0, 0.2, 0.0);
  const Eigen::Vector3d t = TranslationOf(R, {0.0, 0.0, 1.0});
  const testing::TwoViewScene scene = testing::MakeTwoViewScene(camera, R, t, 400, 0.5, 0.4);
  const TwoViewMotion a = EstimateTwoViewMotion(scene.correspondences, camera, {});
  cv::theRNG().state = 12345;  // whatever else ran before must not matter
  cv::theRNG().next();
  const TwoViewMotion b = EstimateTwoViewMotion(scene.correspondences, camera, {});
  EXPECT_EQ(a.rotation, b.rotation);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_EQ(a.inlier_track_ids, b.inlier_track_ids);
}

TEST(TwoViewMotion, CurFromPrevScalesTheDirection) {
  TwoViewMotion motion;
  motion.rotation = testing::RotationFromDegrees(10.0, 0.0, 0.0);
  motion.direction = Eigen::Vector3d(0.0, 0.0, -1.0);
  const Rigid3d cur_from_prev = motion.CurFromPrev(0.86);
  EXPECT_TRUE(cur_from_prev.linear().isApprox(motion.rotation));
  EXPECT_TRUE(cur_from_prev.translation().isApprox(Eigen::Vector3d(0.0, 0.0, -0.86)));
}

TEST(TwoViewMotion, RejectsInvalidOptions) {
  TwoViewMotionOptions options;
  options.ransac_threshold_px = 0.0;
  EXPECT_THROW(options.Check(), Error);
  options = TwoViewMotionOptions();
  options.ransac_confidence = 1.0;
  EXPECT_THROW(options.Check(), Error);
  options = TwoViewMotionOptions();
  options.min_correspondences = 4;
  EXPECT_THROW(options.Check(), Error);
  options = TwoViewMotionOptions();
  options.min_inlier_ratio = 1.5;
  EXPECT_THROW(EstimateTwoViewMotion({}, KittiOdometryCamera(), options), Error);
}

}  // namespace
}  // namespace roadscale
