#include "roadscale/mapping/keyframe_backend.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include "roadscale/testing/mapping_test_scene.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// A perfect segmentation's road mask: a disc around every road point the frame sees.
cv::Mat RoadMask(const testing::MappingTestScene& scene, int frame) {
  cv::Mat mask(scene.camera.height, scene.camera.width, CV_8UC1, cv::Scalar(0));
  for (const TrackObservation& o : scene.Observe(frame, 0.0, 0)) {
    if (!scene.is_road[o.track_id]) continue;
    cv::circle(mask, cv::Point(static_cast<int>(o.pixel.x()), static_cast<int>(o.pixel.y())), 4,
               cv::Scalar(255), cv::FILLED);
  }
  return mask;
}

// `frame_period_s`: the frames' timestamps are f times this (NaN: unknown).
std::vector<MappedFrame> RunBackend(const testing::MappingTestScene& scene, double noise_px,
                                    const MappingOptions& options = {}, bool road_masks = false,
                                    double frame_period_s = std::nan("")) {
  KeyframeBackend backend(scene.camera, scene.camera_height, options, ScaleEstimatorOptions(),
                          TwoViewMotionOptions(), 100);
  std::vector<MappedFrame> mapped;
  for (int f = 0; f < static_cast<int>(scene.cam_from_world.size()); ++f) {
    const cv::Mat mask = road_masks ? RoadMask(scene, f) : cv::Mat();
    for (MappedFrame& m :
         backend.AddFrame(scene.Frontend(f, noise_px, 3), mask, cv::Mat(), f * frame_period_s)) {
      mapped.push_back(std::move(m));
    }
    EXPECT_LE(backend.window().keyframes().size(), 200u);
  }
  for (MappedFrame& m : backend.Finish()) mapped.push_back(std::move(m));
  return mapped;
}

double PathLength(const std::vector<Eigen::Vector3d>& centres) {
  double length = 0.0;
  for (size_t i = 1; i < centres.size(); ++i) length += (centres[i] - centres[i - 1]).norm();
  return length;
}

TEST(KeyframeBackend, GivesEveryFrameAMetricPoseInOrder) {
  const auto scene = testing::MappingTestScene::Street(80, 0.8, 0.3);
  const std::vector<MappedFrame> mapped = RunBackend(scene, 0.2);
  ASSERT_EQ(mapped.size(), scene.cam_from_world.size());
  std::vector<Eigen::Vector3d> estimated, truth;
  int keyframes = 0;
  for (size_t i = 0; i < mapped.size(); ++i) {
    EXPECT_EQ(mapped[i].frame_index, static_cast<int>(i));
    keyframes += mapped[i].keyframe;
    estimated.push_back(mapped[i].world_from_cam.translation());
    truth.push_back(scene.cam_from_world[i].inverse().translation());
  }
  // Keyframes by parallax: fewer than the frames, more than the window.
  EXPECT_LT(keyframes, 60);
  EXPECT_GT(keyframes, 10);
  EXPECT_EQ(mapped.front().localization, MappedFrame::Localization::kKeyframe);
  EXPECT_EQ(mapped.back().scale, MappedFrame::Scale::kRoad);
  // The road makes the map metric: path length and end point within 1 %.
  const double truth_length = PathLength(truth);
  EXPECT_NEAR(PathLength(estimated) / truth_length, 1.0, 0.01);
  EXPECT_LT((estimated.back() - truth.back()).norm(), 0.01 * truth_length);
}

// The first scale is refused where it makes the car faster than first_scale_max_speed: the
// street is driven at 0.8 m a frame, 8 m/s at 10 Hz.
TEST(KeyframeBackend, RefusesAFirstScaleThatMakesTheCarTooFast) {
  const auto scene = testing::MappingTestScene::Street(60, 0.8, 0.3);
  const auto count = [](const std::vector<MappedFrame>& mapped, MappedFrame::Scale scale) {
    return std::count_if(mapped.begin(), mapped.end(),
                         [&](const MappedFrame& m) { return m.scale == scale; });
  };
  const auto refusals = [](const std::vector<MappedFrame>& mapped) {
    return std::count_if(mapped.begin(), mapped.end(),
                         [](const MappedFrame& m) { return m.first_scale_refused; });
  };
  MappingOptions options;
  options.first_scale_max_speed = 5.0;
  const std::vector<MappedFrame> too_fast = RunBackend(scene, 0.2, options, false, 0.1);
  ASSERT_EQ(too_fast.size(), 60u);
  EXPECT_EQ(count(too_fast, MappedFrame::Scale::kNone), 60);
  EXPECT_GT(refusals(too_fast), 5);
  const auto refused = std::find_if(too_fast.begin(), too_fast.end(),
                                    [](const MappedFrame& m) { return m.first_scale_refused; });
  ASSERT_NE(refused, too_fast.end());
  const std::string row = FormatMappedFrameCsv(*refused);
  EXPECT_EQ(row.substr(row.size() - 2), ",1");  // the first_scale_refused column

  options.first_scale_max_speed = 10.0;
  const std::vector<MappedFrame> plausible = RunBackend(scene, 0.2, options, false, 0.1);
  EXPECT_EQ(refusals(plausible), 0);
  EXPECT_EQ(plausible.back().scale, MappedFrame::Scale::kRoad);
  // Without timestamps nothing is refused on speed.
  options.first_scale_max_speed = 5.0;
  EXPECT_EQ(refusals(RunBackend(scene, 0.2, options)), 0);
}

// A window that never holds the road landmarks its own scale needs (min_road_landmarks
// beyond reach) still gets a scale from the keyframe pairs' own road fixes, marked as such;
// without the fallback its frames are unscaled.
TEST(KeyframeBackend, FallsBackToThePairsRoadFixesWhereTheMapGetsNoScale) {
  const auto scene = testing::MappingTestScene::Street(60, 0.8, 0.3);
  MappingOptions options;
  options.bundle_adjustment.min_road_landmarks = 100000;
  const std::vector<MappedFrame> mapped = RunBackend(scene, 0.2, options);
  ASSERT_EQ(mapped.size(), 60u);
  std::vector<Eigen::Vector3d> estimated, truth;
  for (size_t i = 0; i < mapped.size(); ++i) {
    EXPECT_EQ(mapped[i].scale, MappedFrame::Scale::kPairFixes) << "frame " << i;
    estimated.push_back(mapped[i].world_from_cam.translation());
    truth.push_back(scene.cam_from_world[i].inverse().translation());
  }
  EXPECT_NE(FormatMappedFrameCsv(mapped.back()).find(",pair_fixes,"), std::string::npos);
  EXPECT_NEAR(PathLength(estimated) / PathLength(truth), 1.0, 0.05);

  options.fallback_to_pair_fixes = false;
  for (const MappedFrame& m : RunBackend(scene, 0.2, options)) {
    EXPECT_EQ(m.scale, MappedFrame::Scale::kNone);
  }
}

TEST(KeyframeBackend, AStoppedCarKeepsItsPose) {
  auto scene = testing::MappingTestScene::Street(60, 0.8, 0.0);
  // Frames 30-39 stand still at frame 30's pose; the car then drives on.
  for (int f = 31; f < 60; ++f) {
    scene.cam_from_world[f] = f < 40 ? scene.cam_from_world[30] : scene.cam_from_world[f - 9];
  }
  const std::vector<MappedFrame> mapped = RunBackend(scene, 0.2);
  ASSERT_EQ(mapped.size(), 60u);
  for (int f = 31; f < 40; ++f) {
    EXPECT_TRUE(mapped[f].stationary);
    EXPECT_FALSE(mapped[f].keyframe);
    EXPECT_EQ(mapped[f].world_from_cam.translation(), mapped[30].world_from_cam.translation());
  }
  const double truth = (scene.cam_from_world[59].inverse().translation() -
                        scene.cam_from_world[0].inverse().translation())
                           .norm();
  EXPECT_NEAR(
      (mapped[59].world_from_cam.translation() - mapped[0].world_from_cam.translation()).norm() /
          truth,
      1.0, 0.02);
}

// Keeps one road point in `keep_one_in`: a road with little texture.
void ThinTheRoad(testing::MappingTestScene* scene, int keep_one_in) {
  std::vector<Eigen::Vector3d> points;
  std::vector<bool> is_road;
  int road = 0;
  for (size_t i = 0; i < scene->points.size(); ++i) {
    if (scene->is_road[i] && road++ % keep_one_in != 0) continue;
    points.push_back(scene->points[i]);
    is_road.push_back(scene->is_road[i]);
  }
  scene->points = points;
  scene->is_road = is_road;
}

TEST(KeyframeBackend, PoolsTheRoadOfSeveralPairsWhereOnePairSeesTooLittle) {
  auto scene = testing::MappingTestScene::Street(80, 1.5, 0.2);
  // One road point in 80: most keyframe pairs select fewer than road_min_points_per_pair.
  ThinTheRoad(&scene, 80);
  std::vector<Eigen::Vector3d> truth;
  for (const Rigid3d& pose : scene.cam_from_world) truth.push_back(pose.inverse().translation());
  std::map<int, int> keyframes_with_road;
  for (int pool : {1, 3}) {
    MappingOptions options;
    options.road_pool_pairs = pool;
    const std::vector<MappedFrame> mapped = RunBackend(scene, 0.2, options, true);
    ASSERT_EQ(mapped.size(), scene.cam_from_world.size());
    std::vector<Eigen::Vector3d> estimated;
    for (const MappedFrame& m : mapped) {
      estimated.push_back(m.world_from_cam.translation());
      keyframes_with_road[pool] += m.road_points > 0;
    }
    if (pool == 3) {
      EXPECT_NE(mapped.back().scale, MappedFrame::Scale::kNone);
      // The scale rests on a few road points a keyframe: on 40 such streets the path length
      // came within 1.1 % in 9 of 10 and 1.6 % at worst (this street).
      EXPECT_NEAR(PathLength(estimated) / PathLength(truth), 1.0, 0.025);
    }
  }
  EXPECT_GE(keyframes_with_road[3], 2 * keyframes_with_road[1]);
}

// Static points two camera heights under the road, seen through it: what a track that keeps
// catching the next post of a guard rail looks like to the map.
TEST(KeyframeBackend, KeepsNoLandmarksFarBelowTheRoadOnceMetric) {
  auto scene = testing::MappingTestScene::Street(60, 1.0, 0.2);
  const size_t first_below = scene.points.size();
  for (int i = 0; i < 60; ++i) {
    const double x = -6.0 + 0.2 * i;
    const double z = 20.0 + 1.3 * i;
    scene.points.emplace_back(x, 3.0 * scene.camera_height, z);
    scene.is_road.push_back(false);
  }
  const auto below_ground_landmarks = [&](const MappingOptions& options) {
    KeyframeBackend backend(scene.camera, scene.camera_height, options, ScaleEstimatorOptions(),
                            TwoViewMotionOptions(), 100);
    int count = 0;
    for (int f = 0; f < 60; ++f) {
      backend.AddFrame(scene.Frontend(f, 0.2, 3), RoadMask(scene, f));
      if (f < 40) continue;  // the map is metric well before this
      for (const auto& [id, landmark] : backend.window().landmarks()) {
        count += static_cast<size_t>(id) >= first_below;
      }
    }
    return count;
  };
  MappingOptions without_check;
  without_check.landmarks.max_depth_below_ground = 0.0;
  EXPECT_GT(below_ground_landmarks(without_check), 20);
  EXPECT_EQ(below_ground_landmarks(MappingOptions()), 0);
}

TEST(KeyframeBackend, TheWindowStaysBounded) {
  const auto scene = testing::MappingTestScene::Street(100, 1.0, 0.1);
  MappingOptions options;
  options.window_size = 6;
  KeyframeBackend backend(scene.camera, scene.camera_height, options, ScaleEstimatorOptions(),
                          TwoViewMotionOptions(), 100);
  size_t largest = 0;
  for (int f = 0; f < 100; ++f) {
    backend.AddFrame(scene.Frontend(f, 0.2, 3), cv::Mat());
    largest = std::max(largest, backend.window().keyframes().size());
  }
  EXPECT_LE(largest, 7u);
  EXPECT_LT(backend.num_waiting(), 40u);
}

// The scene's frames through a back end with masks, frame `odd` replaced by `odd_frame`.
std::vector<MappedFrame> RunBackendWithOneOddFrame(const testing::MappingTestScene& scene, int odd,
                                                   const FrontendFrame& odd_frame) {
  KeyframeBackend backend(scene.camera, scene.camera_height, MappingOptions(),
                          ScaleEstimatorOptions(), TwoViewMotionOptions(), 100);
  std::vector<MappedFrame> mapped;
  for (int f = 0; f < static_cast<int>(scene.cam_from_world.size()); ++f) {
    const FrontendFrame frontend = f == odd ? odd_frame : scene.Frontend(f, 0.2, 3);
    for (MappedFrame& m : backend.AddFrame(frontend, RoadMask(scene, f))) {
      mapped.push_back(std::move(m));
    }
  }
  for (MappedFrame& m : backend.Finish()) mapped.push_back(std::move(m));
  return mapped;
}

// The map's localisation of a frame against the frame pair's two-view direction and the
// last step (KeyframeBackend::PairOutvotesMap): two against one.
TEST(KeyframeBackend, TheFramePairAndTheLastStepOutvoteTheMapTogetherOnly) {
  const auto scene = testing::MappingTestScene::Street(60, 0.8, 0.2);
  constexpr int kOdd = 40;
  const std::vector<MappedFrame> healthy = RunBackend(scene, 0.2, MappingOptions(), true);
  ASSERT_EQ(healthy.size(), 60u);
  for (const MappedFrame& m : healthy) {
    EXPECT_FALSE(m.pair_outvoted_map) << m.frame_index;
    if (m.map_pair_direction_deg) {
      EXPECT_LT(*m.map_pair_direction_deg, 2.0) << m.frame_index;
    }
  }
  EXPECT_TRUE(healthy[kOdd].map_pair_direction_deg.has_value());

  // The map wrong: the frame's tracks show the camera 0.6 m to the side (a truck passing
  // close moves most tracks so), while the frame pair and the last step go straight on.
  testing::MappingTestScene shifted = scene;
  shifted.cam_from_world[kOdd] =
      MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-0.6, 0.0, 0.0)) *
      scene.cam_from_world[kOdd];
  FrontendFrame map_wrong = shifted.Frontend(kOdd, 0.2, 3);
  map_wrong.motion = scene.Frontend(kOdd, 0.2, 3).motion;
  const std::vector<MappedFrame> outvoted = RunBackendWithOneOddFrame(scene, kOdd, map_wrong);
  ASSERT_EQ(outvoted.size(), 60u);
  ASSERT_TRUE(outvoted[kOdd].map_pair_direction_deg.has_value());
  EXPECT_GT(*outvoted[kOdd].map_pair_direction_deg, 20.0);
  EXPECT_TRUE(outvoted[kOdd].pair_outvoted_map);

  // The pair wrong: its direction 30 degrees to the side (a pair fitted to a vehicle), the
  // map and the last step agree: the map's pose is taken.
  FrontendFrame pair_wrong = scene.Frontend(kOdd, 0.2, 3);
  pair_wrong.motion.direction = Eigen::AngleAxisd(30.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()) *
                                pair_wrong.motion.direction;
  const std::vector<MappedFrame> kept = RunBackendWithOneOddFrame(scene, kOdd, pair_wrong);
  ASSERT_EQ(kept.size(), 60u);
  ASSERT_TRUE(kept[kOdd].map_pair_direction_deg.has_value());
  EXPECT_NEAR(*kept[kOdd].map_pair_direction_deg, 30.0, 2.0);
  EXPECT_FALSE(kept[kOdd].pair_outvoted_map);
  for (int f = kOdd - 1; f <= kOdd + 1; ++f) {
    const Eigen::Vector3d truth = scene.cam_from_world[f].inverse().translation();
    EXPECT_LT((kept[f].world_from_cam.translation() - truth).norm(), 0.05) << f;
  }
}

TEST(MappingOptions, TheShadowBrightnessIsAShareOfTheRoadsLight) {
  MappingOptions options;
  options.road_alignment_shadow_brightness = 0.0;  // off
  EXPECT_NO_THROW(options.Check());
  for (const double wrong : {-0.1, 1.0, std::nan("")}) {
    options.road_alignment_shadow_brightness = wrong;
    EXPECT_THROW(options.Check(), Error) << wrong;
  }
}

}  // namespace
}  // namespace roadscale
