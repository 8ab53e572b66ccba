#include "roadscale/mapping/keyframe_backend.h"

#include <gtest/gtest.h>

#include "roadscale/mapping/mapping_test_scene.h"

namespace roadscale {
namespace {

std::vector<MappedFrame> RunBackend(const testing::MappingTestScene& scene, double noise_px,
                                    const MappingOptions& options = {}) {
  KeyframeBackend backend(scene.camera, scene.camera_height, options, ScaleEstimatorOptions(), 100);
  std::vector<MappedFrame> mapped;
  for (int f = 0; f < static_cast<int>(scene.cam_from_world.size()); ++f) {
    for (MappedFrame& m : backend.AddFrame(scene.Frontend(f, noise_px, 3), cv::Mat())) {
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
  EXPECT_EQ(mapped.front().localization, "keyframe");
  EXPECT_EQ(mapped.back().scale, MappedFrame::Scale::kRoad);
  // The road makes the map metric: path length and end point within 1 %.
  const double truth_length = PathLength(truth);
  EXPECT_NEAR(PathLength(estimated) / truth_length, 1.0, 0.01);
  EXPECT_LT((estimated.back() - truth.back()).norm(), 0.01 * truth_length);
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

TEST(KeyframeBackend, TheWindowStaysBounded) {
  const auto scene = testing::MappingTestScene::Street(100, 1.0, 0.1);
  MappingOptions options;
  options.window_size = 6;
  KeyframeBackend backend(scene.camera, scene.camera_height, options, ScaleEstimatorOptions(), 100);
  size_t largest = 0;
  for (int f = 0; f < 100; ++f) {
    backend.AddFrame(scene.Frontend(f, 0.2, 3), cv::Mat());
    largest = std::max(largest, backend.window().keyframes().size());
  }
  EXPECT_LE(largest, 7u);
  EXPECT_LT(backend.num_waiting(), 40u);
}

}  // namespace
}  // namespace roadscale
