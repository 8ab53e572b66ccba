#include "roadscale/mapping/keyframe_selector.h"

#include <gtest/gtest.h>

#include "roadscale/testing/mapping_test_scene.h"

namespace roadscale {
namespace {

Keyframe KeyframeOf(const testing::MappingTestScene& scene, int frame) {
  Keyframe keyframe;
  keyframe.frame_index = frame;
  keyframe.cam_from_world = scene.cam_from_world[frame];
  for (const TrackObservation& o : scene.Observe(frame, 0.0, 0))
    keyframe.observations[o.track_id] = o.pixel;
  return keyframe;
}

// The first frame after `keyframe` that the selector takes, and why.
std::pair<int, KeyframeReason> NextKeyframe(const testing::MappingTestScene& scene,
                                            int keyframe_frame,
                                            const KeyframeSelectorOptions& options) {
  const Keyframe keyframe = KeyframeOf(scene, keyframe_frame);
  for (int f = keyframe_frame + 1; f < static_cast<int>(scene.cam_from_world.size()); ++f) {
    const Rigid3d cur_from_keyframe = scene.cam_from_world[f] * keyframe.cam_from_world.inverse();
    const bool stationary = cur_from_keyframe.translation().norm() < 1e-9 &&
                            RotationAngle(cur_from_keyframe.linear()) < 1e-9;
    const KeyframeMotion motion = MeasureKeyframeMotion(keyframe, f, scene.Observe(f, 0.0, 0),
                                                        cur_from_keyframe.linear(), scene.camera);
    const KeyframeReason reason = SelectKeyframe(motion, stationary, options);
    if (reason != KeyframeReason::kNone) return {f, reason};
  }
  return {-1, KeyframeReason::kNone};
}

TEST(KeyframeSelector, DrivingStraightTakesKeyframesByParallaxAtAnySpeed) {
  // At 1 m a frame the parallax comes within a few frames; at 5 cm a frame (a car creeping
  // in traffic) after proportionally more frames: the same baseline either way.
  const auto fast = testing::MappingTestScene::Street(40, 1.0, 0.0);
  const auto [fast_frame, fast_reason] = NextKeyframe(fast, 0, {});
  EXPECT_EQ(fast_reason, KeyframeReason::kParallax);
  EXPECT_GE(fast_frame, 1);
  EXPECT_LE(fast_frame, 4);

  const auto slow = testing::MappingTestScene::Street(100, 0.05, 0.0);
  KeyframeSelectorOptions options;
  options.max_frame_gap = 1000;
  const auto [slow_frame, slow_reason] = NextKeyframe(slow, 0, options);
  EXPECT_EQ(slow_reason, KeyframeReason::kParallax);
  // Fast, the near road leaves the view sooner and the median parallax grows slower: the
  // baselines agree to a factor of two.
  EXPECT_GT(slow_frame * 0.05, 0.4 * fast_frame);
  EXPECT_LT(slow_frame * 0.05, 1.6 * fast_frame);
}

TEST(KeyframeSelector, AStoppedCarTakesNoKeyframe) {
  auto scene = testing::MappingTestScene::Street(40, 1.0, 0.0);
  for (size_t f = 1; f < scene.cam_from_world.size(); ++f)
    scene.cam_from_world[f] = scene.cam_from_world[0];
  EXPECT_EQ(NextKeyframe(scene, 0, {}).first, -1);
}

TEST(KeyframeSelector, ATurnOnTheSpotRenewsTheKeyframeWhenItsTracksLeave) {
  // Pure rotation: no parallax, but the view leaves the keyframe's tracks behind.
  auto scene = testing::MappingTestScene::Street(40, 1.0, 0.0);
  for (size_t f = 1; f < scene.cam_from_world.size(); ++f) {
    scene.cam_from_world[f] =
        MakeRigid3d(
            Eigen::AngleAxisd(2.0 * f * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix(),
            Eigen::Vector3d::Zero()) *
        scene.cam_from_world[0];
  }
  const auto [frame, reason] = NextKeyframe(scene, 0, {});
  EXPECT_EQ(reason, KeyframeReason::kTrackedShare);
  EXPECT_GT(frame, 3);
}

TEST(KeyframeSelector, AFrameGapForcesAKeyframe) {
  const auto scene = testing::MappingTestScene::Street(60, 0.005, 0.0);
  KeyframeSelectorOptions options;
  options.max_frame_gap = 25;
  const auto [frame, reason] = NextKeyframe(scene, 0, options);
  EXPECT_EQ(reason, KeyframeReason::kFrameGap);
  EXPECT_EQ(frame, 25);
}

TEST(KeyframeSelector, AFrameWithoutTracksIsNoKeyframe) {
  // A black frame: no track is seen, so every reason would hold, yet the map gains nothing.
  const auto scene = testing::MappingTestScene::Street(40, 1.0, 0.0);
  const Keyframe keyframe = KeyframeOf(scene, 0);
  const Rigid3d cur_from_keyframe = scene.cam_from_world[35] * keyframe.cam_from_world.inverse();
  const KeyframeMotion blank =
      MeasureKeyframeMotion(keyframe, 35, {}, cur_from_keyframe.linear(), scene.camera);
  EXPECT_EQ(blank.num_observations, 0);
  EXPECT_EQ(SelectKeyframe(blank, false, {}), KeyframeReason::kNone);
  const KeyframeMotion seen = MeasureKeyframeMotion(keyframe, 35, scene.Observe(35, 0.0, 0),
                                                    cur_from_keyframe.linear(), scene.camera);
  EXPECT_GT(seen.num_observations, 0);
  EXPECT_NE(SelectKeyframe(seen, false, {}), KeyframeReason::kNone);
}

}  // namespace
}  // namespace roadscale
