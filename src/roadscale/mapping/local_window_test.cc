#include "roadscale/mapping/local_window.h"

#include <gtest/gtest.h>

namespace roadscale {
namespace {

Keyframe KeyframeSeeing(int frame_index, std::initializer_list<int64_t> track_ids) {
  Keyframe keyframe;
  keyframe.frame_index = frame_index;
  for (int64_t id : track_ids) keyframe.observations[id] = Eigen::Vector2d(10.0 * id, 5.0);
  return keyframe;
}

TEST(LocalWindow, RemoveTrackErasesItsObservationsAndLandmarkOnly) {
  LocalWindow window;
  window.AddKeyframe(KeyframeSeeing(0, {1, 2, 3}));
  window.AddKeyframe(KeyframeSeeing(1, {1, 2, 3}));
  window.AddKeyframe(KeyframeSeeing(2, {2, 3}));
  for (int64_t id : {1, 2, 3}) window.landmarks()[id].position = Eigen::Vector3d(id, 0.0, 5.0);

  window.RemoveTrack(2);
  EXPECT_EQ(window.CountObservations(2), 0);
  EXPECT_EQ(window.landmarks().count(2), 0u);
  EXPECT_EQ(window.CountObservations(1), 2);
  EXPECT_EQ(window.CountObservations(3), 3);
  EXPECT_EQ(window.landmarks().size(), 2u);
  window.RemoveTrack(42);  // unknown: nothing happens
  EXPECT_EQ(window.landmarks().size(), 2u);
}

TEST(LocalWindow, RemoveOldestKeyframeDropsLandmarksSeenOnceAndRoadMarksOfIt) {
  LocalWindow window;
  window.AddKeyframe(KeyframeSeeing(0, {1, 2}));
  window.AddKeyframe(KeyframeSeeing(1, {1, 2}));
  window.AddKeyframe(KeyframeSeeing(2, {2}));
  window.landmarks()[1];
  Landmark& road = window.landmarks()[2];
  road.is_road = true;
  road.road_anchor_frame = 0;

  window.RemoveOldestKeyframe();
  EXPECT_EQ(window.landmarks().count(1), 0u);  // left with one observation
  ASSERT_EQ(window.landmarks().count(2), 1u);
  EXPECT_FALSE(window.landmarks().at(2).is_road);  // its anchor left
  EXPECT_EQ(window.CountRoadLandmarks(), 0);
}

TEST(LocalWindow, RescaledPoseMovesAPoseAsRescaleMovesTheKeyframes) {
  LocalWindow window;
  const Rigid3d oldest = MakeRigid3d(
      Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix(), {1.0, 0.5, -2.0});
  const Rigid3d newer = MakeRigid3d(
      Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()).toRotationMatrix(), {0.2, 0.4, -6.0});
  window.AddKeyframe(KeyframeSeeing(0, {}));
  window.AddKeyframe(KeyframeSeeing(3, {}));
  window.keyframes()[0].cam_from_world = oldest;
  window.keyframes()[1].cam_from_world = newer;

  const Rigid3d predicted = window.RescaledPose(newer, 2.5);
  window.Rescale(2.5);
  EXPECT_LT((window.keyframes()[1].cam_from_world.matrix() - predicted.matrix()).norm(), 1e-12);
  EXPECT_LT((window.keyframes()[0].cam_from_world.matrix() - oldest.matrix()).norm(), 1e-12);
  // The oldest keyframe's centre is the fixed point: after Rescale the same answer.
  EXPECT_LT((window.RescaledPose(newer, 2.5).matrix() - predicted.matrix()).norm(), 1e-12);
  const double before = (newer.inverse().translation() - oldest.inverse().translation()).norm();
  const double after = (predicted.inverse().translation() - oldest.inverse().translation()).norm();
  EXPECT_NEAR(after / before, 2.5, 1e-12);
}

}  // namespace
}  // namespace roadscale
