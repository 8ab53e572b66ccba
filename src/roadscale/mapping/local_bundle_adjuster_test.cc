#include "roadscale/mapping/local_bundle_adjuster.h"

#include <gtest/gtest.h>

#include "roadscale/testing/mapping_test_scene.h"
#include "roadscale/util/random.h"

namespace roadscale {
namespace {

Eigen::Vector3d Centre(const Rigid3d& cam_from_world) {
  return cam_from_world.inverse().translation();
}

// Pixel noise on every observation, and a share of the observations replaced by wrong
// pixels (tracks that slipped). One draw a statement here and below: the order of a call's
// arguments is the compiler's, and the test must be the same with every compiler.
void Corrupt(LocalWindow* window, double noise_px, double outlier_share, uint32_t seed) {
  Rng rng(seed);
  for (Keyframe& keyframe : window->keyframes()) {
    for (auto& [id, pixel] : keyframe.observations) {
      if (rng.Bernoulli(outlier_share)) {
        const double dy = rng.Uniform(-50.0, -20.0);
        const double dx = rng.Uniform(20.0, 50.0);
        pixel += Eigen::Vector2d(dx, dy);
      } else {
        const double dy = noise_px * rng.Normal();
        const double dx = noise_px * rng.Normal();
        pixel += Eigen::Vector2d(dx, dy);
      }
    }
  }
}

// Each coordinate uniform in [-1, 1).
Eigen::Vector3d RandomVector(Rng& rng) {
  const double z = rng.Uniform(-1.0, 1.0);
  const double y = rng.Uniform(-1.0, 1.0);
  const double x = rng.Uniform(-1.0, 1.0);
  return {x, y, z};
}

// Moves the keyframes from `first_moved` on by up to `pose_noise` metres and 0.3 deg, and
// every landmark by up to 3 % of its depth.
void Perturb(LocalWindow* window, size_t first_moved, double pose_noise, uint32_t seed) {
  Rng rng(seed);
  for (size_t k = first_moved; k < window->keyframes().size(); ++k) {
    Rigid3d& pose = window->keyframes()[k].cam_from_world;
    const Eigen::Vector3d axis = RandomVector(rng).normalized();
    pose = MakeRigid3d(Eigen::AngleAxisd(0.3 * M_PI / 180.0, axis).toRotationMatrix(),
                       pose_noise * RandomVector(rng)) *
           pose;
  }
  for (auto& [id, landmark] : window->landmarks()) {
    landmark.position *= 1.0 + 0.03 * rng.Uniform(-1.0, 1.0);
  }
}

// The largest distance between the centres of the same keyframe in two windows.
double MaxCentreDistance(const LocalWindow& a, const LocalWindow& b) {
  double worst = 0.0;
  for (size_t k = 0; k < a.keyframes().size(); ++k) {
    worst = std::max(
        worst,
        (Centre(a.keyframes()[k].cam_from_world) - Centre(b.keyframes()[k].cam_from_world)).norm());
  }
  return worst;
}

// The largest angle between the orientations of the same keyframe in two windows, degrees.
double MaxRotationDifferenceDeg(const LocalWindow& a, const LocalWindow& b) {
  double worst = 0.0;
  for (size_t k = 0; k < a.keyframes().size(); ++k) {
    const Eigen::Matrix3d difference = a.keyframes()[k].cam_from_world.linear() *
                                       b.keyframes()[k].cam_from_world.linear().transpose();
    worst = std::max(worst, RotationAngle(difference) * 180.0 / M_PI);
  }
  return worst;
}

// The window's first-to-last keyframe distance over the true one (the window's scale).
double LengthOverTruth(const LocalWindow& window, const testing::MappingTestScene& scene) {
  const Keyframe& first = window.keyframes().front();
  const Keyframe& last = window.keyframes().back();
  const double true_length = (Centre(scene.cam_from_world[last.frame_index]) -
                              Centre(scene.cam_from_world[first.frame_index]))
                                 .norm();
  return (Centre(last.cam_from_world) - Centre(first.cam_from_world)).norm() / true_length;
}

double MaxCentreError(const LocalWindow& window, const testing::MappingTestScene& scene) {
  double worst = 0.0;
  for (const Keyframe& keyframe : window.keyframes()) {
    worst = std::max(worst, (Centre(keyframe.cam_from_world) -
                             Centre(scene.cam_from_world[keyframe.frame_index]))
                                .norm());
  }
  return worst;
}

TEST(LocalBundleAdjuster, RecoversPosesAndLandmarksFromNoiseAndOutliers) {
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.4);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  for (auto& [id, landmark] : window.landmarks()) landmark.is_road = false;  // reprojection only
  Corrupt(&window, 0.3, 0.1, 1);
  // What the same observations give from the exact poses: the adjustment's optimum, which it
  // must reach from the perturbed start.
  LocalWindow from_exact = window;
  Perturb(&window, 2, 0.3, 2);  // the two oldest keyframes hold the gauge and the scale
  ASSERT_GT(MaxCentreError(window, scene), 0.1);

  LocalBundleAdjusterOptions options;
  options.max_iterations = 30;
  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, options, &window);
  AdjustLocalWindow(scene.camera, 1.65, options, &from_exact);
  EXPECT_TRUE(report.ran);
  EXPECT_FALSE(report.scale_from_road);
  EXPECT_LT(report.final_cost, report.initial_cost);  // the outliers keep most of it
  // From 0.3-0.5 m and 0.3 deg off to the optimum (60 draws of scene, noise and perturbation:
  // at most 9 mm and 0.004 deg from it).
  EXPECT_LT(MaxCentreDistance(window, from_exact), 0.02);
  EXPECT_LT(MaxRotationDifferenceDeg(window, from_exact), 0.01);
  // The optimum itself is as far from the truth as the noise and the outliers put it: the two
  // oldest keyframes, 3 m apart, carry the scale over the window's 27 m (no road landmarks).
  // The same 60 draws: at most 0.12 m and 0.034 deg (median 0.03 m and 0.018 deg).
  EXPECT_LT(MaxCentreError(window, scene), 0.15);
  for (const Keyframe& keyframe : window.keyframes()) {
    const Eigen::Matrix3d error = keyframe.cam_from_world.linear() *
                                  scene.cam_from_world[keyframe.frame_index].linear().transpose();
    EXPECT_LT(RotationAngle(error) * 180.0 / M_PI, 0.05);
  }
  // Most outliers removed, few good observations lost.
  EXPECT_GT(report.removed_observations, 0);
  int near_points = 0, accurate = 0;
  for (const auto& [id, landmark] : window.landmarks()) {
    const double depth = (scene.cam_from_world[0] * scene.points[id]).z();
    if (depth > 20.0) continue;
    ++near_points;
    if ((landmark.position - scene.points[id]).norm() < 0.01 * depth) ++accurate;
  }
  EXPECT_GT(accurate, 0.9 * near_points);
}

TEST(LocalBundleAdjuster, ALandmarkBehindOneKeyframeDoesNotStopTheAdjustment) {
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.4);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  for (auto& [id, landmark] : window.landmarks()) landmark.is_road = false;
  Perturb(&window, 2, 0.3, 2);
  ASSERT_GT(MaxCentreError(window, scene), 0.1);
  // One landmark seen by the newest keyframe moved 1 m behind it (a wrong triangulation):
  // its reprojection there cannot be evaluated, and Ceres gives up on a window whose start
  // it cannot evaluate.
  const Keyframe& newest = window.keyframes().back();
  ASSERT_FALSE(newest.observations.empty());
  const int64_t moved = newest.observations.begin()->first;
  const Eigen::Vector3d forward = newest.cam_from_world.linear().transpose().col(2);
  window.landmarks().at(moved).position = Centre(newest.cam_from_world) - forward;

  LocalBundleAdjusterOptions options;
  options.max_iterations = 30;
  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, options, &window);
  EXPECT_TRUE(report.ran);
  EXPECT_GT(report.iterations, 0);
  EXPECT_LT(report.final_cost, report.initial_cost);
  EXPECT_LT(MaxCentreError(window, scene), 0.03);
  // Its other views bring it back to where it belongs.
  const double depth = (scene.cam_from_world[0] * scene.points[moved]).z();
  EXPECT_LT((window.landmarks().at(moved).position - scene.points[moved]).norm(), 0.02 * depth);
}

TEST(LocalBundleAdjuster, TheGaugeFollowsTheOldestKeyframe) {
  // The same window moved and turned as a whole: the adjustment gives the same window,
  // moved and turned the same way - nothing but the oldest keyframe anchors it.
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.4);
  LocalWindow window = testing::ExactWindow(scene, 8, 3);
  Corrupt(&window, 0.3, 0.0, 3);
  Perturb(&window, 1, 0.2, 4);
  LocalWindow moved = window;
  const Rigid3d world2_from_world = MakeRigid3d(
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 1.0, 0.1).normalized()).toRotationMatrix(),
      Eigen::Vector3d(15.0, -2.0, 40.0));
  for (Keyframe& keyframe : moved.keyframes()) {
    keyframe.cam_from_world = keyframe.cam_from_world * world2_from_world.inverse();
  }
  for (auto& [id, landmark] : moved.landmarks())
    landmark.position = world2_from_world * landmark.position;

  AdjustLocalWindow(scene.camera, 1.65, {}, &window);
  AdjustLocalWindow(scene.camera, 1.65, {}, &moved);
  ASSERT_EQ(window.keyframes().size(), moved.keyframes().size());
  for (size_t k = 0; k < window.keyframes().size(); ++k) {
    const Rigid3d expected = window.keyframes()[k].cam_from_world * world2_from_world.inverse();
    EXPECT_LT((moved.keyframes()[k].cam_from_world.matrix() - expected.matrix()).norm(), 1e-5);
  }
  // The oldest keyframe did not move.
  EXPECT_LT(
      (Centre(window.keyframes().front().cam_from_world) - Centre(scene.cam_from_world[0])).norm(),
      1e-12);
}

TEST(LocalBundleAdjuster, AnOldestKeyframeWithoutResidualsLeavesTheGaugeToTheNextOne) {
  // The oldest keyframe has lost every observation and anchors no road landmark, so it is not
  // in the problem: the oldest keyframe that is must hold the gauge.
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.4);
  LocalWindow window = testing::ExactWindow(scene, 8, 3);
  Keyframe& oldest = window.keyframes().front();
  std::vector<int64_t> seen;
  for (const auto& [id, pixel] : oldest.observations) seen.push_back(id);
  for (int64_t id : seen) window.RemoveObservation(&oldest, id);
  for (auto& [id, landmark] : window.landmarks()) {
    if (landmark.road_anchor_frame == oldest.frame_index) landmark.is_road = false;
  }
  Corrupt(&window, 0.3, 0.0, 3);
  Perturb(&window, 2, 0.2, 4);
  const Rigid3d second = window.keyframes()[1].cam_from_world;

  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, {}, &window);
  ASSERT_TRUE(report.scale_from_road);
  EXPECT_LT((window.keyframes()[1].cam_from_world.matrix() - second.matrix()).norm(), 1e-12);
  EXPECT_LT(MaxCentreError(window, scene), 0.1);
}

constexpr size_t kFirstOfSecondPart = 4;

// An exact window of 8 keyframes in which every track is lost between keyframes 3 and 4 (a
// black frame): no landmark is seen from both sides.
LocalWindow WindowInTwoParts(const testing::MappingTestScene& scene) {
  LocalWindow window = testing::ExactWindow(scene, 8, 3);
  int second_part_only = 0;
  std::vector<int64_t> seen_before;
  for (const auto& [id, landmark] : window.landmarks()) {
    bool before = false;
    for (size_t k = 0; k < kFirstOfSecondPart; ++k) {
      before |= window.keyframes()[k].observations.count(id) > 0;
    }
    if (before) {
      seen_before.push_back(id);
    } else {
      ++second_part_only;
    }
  }
  for (int64_t id : seen_before) {
    for (size_t k = kFirstOfSecondPart; k < window.keyframes().size(); ++k) {
      if (window.keyframes()[k].observations.count(id)) {
        window.RemoveObservation(&window.keyframes()[k], id);
      }
    }
  }
  EXPECT_GE(second_part_only, 50);
  return window;
}

TEST(LocalBundleAdjuster, EachUnlinkedPartOfTheWindowHoldsItsOwnGauge) {
  // Keyframe 4's place is only the motion's prediction: it holds the second part.
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.4);
  LocalWindow window = WindowInTwoParts(scene);
  Corrupt(&window, 0.3, 0.0, 3);
  Perturb(&window, kFirstOfSecondPart, 0.2, 4);
  const Rigid3d first_of_second = window.keyframes()[kFirstOfSecondPart].cam_from_world;

  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, {}, &window);
  ASSERT_TRUE(report.scale_from_road);
  EXPECT_LT(
      (window.keyframes()[kFirstOfSecondPart].cam_from_world.matrix() - first_of_second.matrix())
          .norm(),
      1e-12);
  // Within the second part the road still makes the map metric.
  const size_t last = window.keyframes().size() - 1;
  const double true_length = (Centre(scene.cam_from_world[window.keyframes()[last].frame_index]) -
                              Centre(scene.cam_from_world[window.keyframes()[4].frame_index]))
                                 .norm();
  EXPECT_NEAR((Centre(window.keyframes()[last].cam_from_world) - Centre(first_of_second)).norm() /
                  true_length,
              1.0, 0.01);
}

TEST(LocalBundleAdjuster, AnUnlinkedPartWithoutRoadHoldsItsScaleToo) {
  // The first part's road sets its scale, but none of it reaches the second part, whose scale
  // only its first two keyframes can hold.
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.4);
  LocalWindow window = WindowInTwoParts(scene);
  for (auto& [id, landmark] : window.landmarks()) {
    const Keyframe* anchor = window.FindKeyframe(landmark.road_anchor_frame);
    if (anchor != nullptr && anchor->frame_index >= window.keyframes()[4].frame_index) {
      landmark.is_road = false;
    }
  }
  Corrupt(&window, 0.3, 0.0, 3);
  Perturb(&window, kFirstOfSecondPart, 0.2, 4);
  const Rigid3d first = window.keyframes()[kFirstOfSecondPart].cam_from_world;
  const Rigid3d second = window.keyframes()[kFirstOfSecondPart + 1].cam_from_world;

  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, {}, &window);
  ASSERT_TRUE(report.scale_from_road);
  EXPECT_LT(
      (window.keyframes()[kFirstOfSecondPart].cam_from_world.matrix() - first.matrix()).norm(),
      1e-12);
  EXPECT_LT(
      (window.keyframes()[kFirstOfSecondPart + 1].cam_from_world.matrix() - second.matrix()).norm(),
      1e-12);
}

class LocalBundleAdjusterScale : public ::testing::TestWithParam<double> {};

TEST_P(LocalBundleAdjusterScale, TheCameraHeightTermMakesAWrongScaleMetric) {
  const double wrong_scale = GetParam();
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.3);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  Corrupt(&window, 0.3, 0.05, 5);
  window.Rescale(wrong_scale);
  ASSERT_GE(window.CountRoadLandmarks(), 100);

  LocalBundleAdjusterOptions options;
  options.max_iterations = 30;
  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, options, &window);
  EXPECT_TRUE(report.scale_from_road);
  EXPECT_NEAR(LengthOverTruth(window, scene), 1.0, 0.005) << "started at " << wrong_scale << "x";
  EXPECT_LT(MaxCentreError(window, scene), 0.1);
}

INSTANTIATE_TEST_SUITE_P(TwiceAndHalf, LocalBundleAdjusterScale, ::testing::Values(2.0, 0.5));

// Road alignments of the keyframe pairs alone (no road landmark) make the window metric: each
// pair's exact camera height per baseline, h0 / |c_k - c_k-1|.
TEST_P(LocalBundleAdjusterScale, ThePairTermMakesAWrongScaleMetric) {
  const double wrong_scale = GetParam();
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.3);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  for (auto& [id, landmark] : window.landmarks()) landmark.is_road = false;
  for (size_t k = 1; k < window.keyframes().size(); ++k) {
    Keyframe& keyframe = window.keyframes()[k];
    const Keyframe& anchor = window.keyframes()[k - 1];
    const double baseline =
        (Centre(keyframe.cam_from_world) - Centre(anchor.cam_from_world)).norm();
    keyframe.road_pair = RoadPairPlane{anchor.frame_index, 1.65 / baseline};
  }
  Corrupt(&window, 0.3, 0.05, 5);
  window.Rescale(wrong_scale);
  ASSERT_EQ(window.CountRoadLandmarks(), 0);
  ASSERT_EQ(window.CountRoadPairs(), 9);

  LocalBundleAdjusterOptions options;
  options.max_iterations = 30;
  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, options, &window);
  EXPECT_TRUE(report.scale_from_road);
  EXPECT_EQ(report.num_road_pairs, 9);
  EXPECT_NEAR(LengthOverTruth(window, scene), 1.0, 0.005) << "started at " << wrong_scale << "x";
  EXPECT_LT(MaxCentreError(window, scene), 0.1);
}

// A pair term far off the adjusted window (a wrong alignment) is dropped after the solve; one
// measured on the region ahead without segmentation stays as a reading outside the adjustment.
TEST(LocalBundleAdjuster, DropsAPairTermFarOffTheWindow) {
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.3);
  for (const bool on_road_mask : {true, false}) {
    LocalWindow window = testing::ExactWindow(scene, 10, 3);
    Keyframe& keyframe = window.keyframes()[5];
    keyframe.road_pair = RoadPairPlane{window.keyframes()[4].frame_index, 1.65 * 1.5 / 3.0};
    keyframe.road_pair->on_road_mask = on_road_mask;
    const BundleAdjustmentReport report =
        AdjustLocalWindow(scene.camera, 1.65, LocalBundleAdjusterOptions(), &window);
    EXPECT_EQ(report.num_road_pairs, 1);
    EXPECT_EQ(window.CountRoadPairs(), 0);
    EXPECT_EQ(window.CountRoadPairReadings(), on_road_mask ? 0 : 1);
    EXPECT_GE(report.removed_road_marks, 1);
  }
}

// A pair of the region ahead taken out alone still votes: when two more pairs come that agree
// with it (the map's scale is off), the three outvote the map and all three are in the
// adjustment.
TEST(LocalBundleAdjuster, PutsARegionPairTermBackWhenLaterPairsAgreeWithIt) {
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.3);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  ASSERT_GE(window.CountRoadLandmarks(), 100);
  const auto add_pair = [&window](size_t k) {
    Keyframe& keyframe = window.keyframes()[k];
    const Keyframe& anchor = window.keyframes()[k - 1];
    const double baseline =
        (Centre(keyframe.cam_from_world) - Centre(anchor.cam_from_world)).norm();
    keyframe.road_pair = RoadPairPlane{anchor.frame_index, 1.65 * 1.1 / baseline};
    keyframe.road_pair->on_road_mask = false;
  };
  add_pair(3);
  AdjustLocalWindow(scene.camera, 1.65, LocalBundleAdjusterOptions(), &window);
  ASSERT_FALSE(window.keyframes()[3].road_pair->in_adjustment);
  add_pair(4);
  add_pair(5);
  AdjustLocalWindow(scene.camera, 1.65, LocalBundleAdjusterOptions(), &window);
  EXPECT_EQ(window.CountRoadPairs(), 3);
  EXPECT_TRUE(window.keyframes()[3].road_pair->in_adjustment);
}

// Pairs that agree with each other outvote the map: nine alignments that all put the camera
// 10 % higher than the exact road landmarks do are kept (the map has drifted, as far as they
// can tell); one alignment among them far from the rest and from the map is still dropped.
TEST(LocalBundleAdjuster, KeepsPairTermsThatAgreeWithEachOtherButNotWithTheMap) {
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.3);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  ASSERT_GE(window.CountRoadLandmarks(), 100);
  for (size_t k = 1; k < window.keyframes().size(); ++k) {
    Keyframe& keyframe = window.keyframes()[k];
    const Keyframe& anchor = window.keyframes()[k - 1];
    const double baseline =
        (Centre(keyframe.cam_from_world) - Centre(anchor.cam_from_world)).norm();
    const double height = k == 5 ? 1.65 * 1.6 : 1.65 * 1.1;
    keyframe.road_pair = RoadPairPlane{anchor.frame_index, height / baseline};
  }
  const BundleAdjustmentReport report =
      AdjustLocalWindow(scene.camera, 1.65, LocalBundleAdjusterOptions(), &window);
  EXPECT_EQ(report.num_road_pairs, 9);
  EXPECT_EQ(window.CountRoadPairs(), 8);
  EXPECT_FALSE(window.keyframes()[5].road_pair.has_value());
  // Each kept pair is off the adjusted map by more than the outlier bound (4 sigmas of
  // 0.02 m): the map alone would have dropped it.
  const LocalBundleAdjusterOptions options;
  for (size_t k = 1; k < window.keyframes().size(); ++k) {
    const Keyframe& keyframe = window.keyframes()[k];
    if (!keyframe.road_pair) continue;
    const double baseline =
        (Centre(keyframe.cam_from_world) - Centre(window.keyframes()[k - 1].cam_from_world)).norm();
    EXPECT_GT(std::abs(keyframe.road_pair->height_per_baseline * baseline - 1.65),
              options.road_outlier_sigmas * options.road_pair_sigma_m)
        << "keyframe " << k;
  }
}

// Three alignments of the region ahead far off the map and off each other (a car in the
// region): their median is one of them, not a consensus, and none of them outvotes the map.
TEST(LocalBundleAdjuster, PairsThatDisagreeWithEachOtherDoNotOutvoteTheMap) {
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.3);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  ASSERT_GE(window.CountRoadLandmarks(), 100);
  const double factors[] = {3.9, 4.7, 5.8};
  for (size_t k = 3; k <= 5; ++k) {
    Keyframe& keyframe = window.keyframes()[k];
    const Keyframe& anchor = window.keyframes()[k - 1];
    const double baseline =
        (Centre(keyframe.cam_from_world) - Centre(anchor.cam_from_world)).norm();
    keyframe.road_pair = RoadPairPlane{anchor.frame_index, 1.65 * factors[k - 3] / baseline};
    keyframe.road_pair->on_road_mask = false;
  }
  AdjustLocalWindow(scene.camera, 1.65, LocalBundleAdjusterOptions(), &window);
  EXPECT_EQ(window.CountRoadPairs(), 0);
  EXPECT_EQ(window.CountRoadPairReadings(), 3);
}

TEST(LocalBundleAdjuster, FewRoadLandmarksLeaveTheScaleToTheMap) {
  const auto scene = testing::MappingTestScene::Street(30, 1.0, 0.3);
  LocalWindow window = testing::ExactWindow(scene, 10, 3);
  int kept = 0;
  for (auto& [id, landmark] : window.landmarks()) {
    if (landmark.is_road && ++kept > 10) landmark.is_road = false;
  }
  window.Rescale(1.2);
  LocalBundleAdjusterOptions options;
  const BundleAdjustmentReport report = AdjustLocalWindow(scene.camera, 1.65, options, &window);
  EXPECT_FALSE(report.scale_from_road);
  EXPECT_NEAR(LengthOverTruth(window, scene), 1.2, 0.01);
}

}  // namespace
}  // namespace roadscale
