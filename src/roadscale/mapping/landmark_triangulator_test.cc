#include "roadscale/mapping/landmark_triangulator.h"

#include <gtest/gtest.h>

#include "roadscale/testing/mapping_test_scene.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(TriangulateMultiView, RecoversAPointFromThreeViews) {
  const testing::MappingTestScene scene = testing::MappingTestScene::Street(10, 1.0, 0.5);
  const Eigen::Vector3d point(1.5, 1.65, 12.0);
  std::vector<PointView> views;
  for (int f : {0, 2, 4}) {
    views.push_back(
        {scene.cam_from_world[f], scene.camera.Project(scene.cam_from_world[f] * point)});
  }
  const auto triangulated = TriangulateMultiView(views, scene.camera, {});
  ASSERT_TRUE(triangulated.has_value());
  EXPECT_LT((*triangulated - point).norm(), 1e-6);
}

TEST(TriangulateMultiView, RejectsTooSmallAnAngleAndAWrongView) {
  const testing::MappingTestScene scene = testing::MappingTestScene::Street(10, 1.0, 0.0);
  // Straight ahead, 50 m away, 1 m of baseline: the rays meet at 0.03 deg.
  const Eigen::Vector3d far_point(0.2, 0.5, 50.0);
  std::vector<PointView> views;
  for (int f : {0, 1}) {
    views.push_back(
        {scene.cam_from_world[f], scene.camera.Project(scene.cam_from_world[f] * far_point)});
  }
  EXPECT_FALSE(TriangulateMultiView(views, scene.camera, {}).has_value());

  const Eigen::Vector3d point(3.0, 1.65, 8.0);
  views.clear();
  for (int f : {0, 3, 6}) {
    views.push_back(
        {scene.cam_from_world[f], scene.camera.Project(scene.cam_from_world[f] * point)});
  }
  ASSERT_TRUE(TriangulateMultiView(views, scene.camera, {}).has_value());
  views[1].pixel.x() += 5.0;  // a track that slipped in the middle view
  EXPECT_FALSE(TriangulateMultiView(views, scene.camera, {}).has_value());
}

TEST(TriangulateNewLandmarks, MakesLandmarksOfTracksSeenInEarlierKeyframesOnly) {
  const testing::MappingTestScene scene = testing::MappingTestScene::Street(12, 1.0, 0.3);
  LocalWindow window;
  for (int f : {0, 5, 10}) {
    Keyframe keyframe;
    keyframe.frame_index = f;
    keyframe.cam_from_world = scene.cam_from_world[f];
    for (const TrackObservation& o : scene.Observe(f, 0.0, 0))
      keyframe.observations[o.track_id] = o.pixel;
    window.AddKeyframe(std::move(keyframe));
  }
  const int created = TriangulateNewLandmarks(scene.camera, {}, &window);
  EXPECT_GT(created, 200);
  EXPECT_EQ(created, static_cast<int>(window.landmarks().size()));
  for (const auto& [id, landmark] : window.landmarks()) {
    EXPECT_GE(window.CountObservations(id), 2);
    EXPECT_LT((landmark.position - scene.points[id]).norm(), 1e-6 * scene.points[id].norm() + 1e-6);
  }
  // Tracks only the newest keyframe sees stay without a landmark.
  for (const auto& [id, pixel] : window.keyframes().back().observations) {
    if (window.CountObservations(id) == 1) {
      EXPECT_EQ(window.landmarks().count(id), 0u);
    }
  }
}

// A track that caught the next post of a guard rail, or a stripe's neighbour, moves less
// than the point it started on: its rays meet far beyond the ground, below the road plane.
TEST(RemoveLandmarksBelowGround, ErasesTheTracksFarBelowTheRoadOnly) {
  const testing::MappingTestScene scene = testing::MappingTestScene::Street(3, 1.0, 0.0);
  const Eigen::Vector3d road_point(2.0, 1.65, 12.0);
  const Eigen::Vector3d below_ground = 3.0 * road_point;  // seen where the road point is
  const int64_t road_id = 1, below_id = 2;
  const auto window_of_both = [&] {
    LocalWindow window;
    for (int f : {0, 1, 2}) {
      Keyframe keyframe;
      keyframe.frame_index = f;
      keyframe.cam_from_world = scene.cam_from_world[f];
      keyframe.observations[road_id] = scene.camera.Project(scene.cam_from_world[f] * road_point);
      keyframe.observations[below_id] =
          scene.camera.Project(scene.cam_from_world[f] * below_ground);
      window.AddKeyframe(std::move(keyframe));
    }
    EXPECT_EQ(TriangulateNewLandmarks(scene.camera, {}, &window), 2);
    return window;
  };
  const Plane ground{Eigen::Vector3d::UnitY(), 1.65};
  LandmarkTriangulatorOptions options;
  options.max_depth_below_ground = 1.0;

  LocalWindow window = window_of_both();
  EXPECT_EQ(RemoveLandmarksBelowGround(ground, options, &window), 1);
  EXPECT_EQ(window.landmarks().count(road_id), 1u);
  EXPECT_EQ(window.landmarks().count(below_id), 0u);
  EXPECT_EQ(window.CountObservations(below_id), 0);  // not triangulated again from them
  EXPECT_EQ(window.CountObservations(road_id), 3);

  options.max_depth_below_ground = 2.5;  // three heights under the camera: within 3.5
  LocalWindow tolerant = window_of_both();
  EXPECT_EQ(RemoveLandmarksBelowGround(ground, options, &tolerant), 0);
  options.max_depth_below_ground = 0.0;  // no check
  EXPECT_EQ(RemoveLandmarksBelowGround(ground, options, &tolerant), 0);
}

TEST(LandmarkTriangulatorOptions, RejectsANegativeDepthBelowTheGround) {
  LandmarkTriangulatorOptions options;
  EXPECT_NO_THROW(options.Check());
  options.max_depth_below_ground = 0.0;  // no check
  EXPECT_NO_THROW(options.Check());
  options.max_depth_below_ground = -1.0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale
