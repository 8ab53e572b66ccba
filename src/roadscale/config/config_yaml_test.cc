#include "roadscale/config/config_yaml.h"

#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::string WriteFile(const testing::TempDir& dir, const std::string& text) {
  const std::string path = (dir.path() / "config.yaml").string();
  std::ofstream(path) << text;
  return path;
}

std::string ErrorOf(const std::string& path) {
  RunConfig config;
  try {
    ReadRunConfig(path, &config);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(RunConfigYaml, DefaultsAreTheModulesDefaults) {
  const RunConfig config;
  EXPECT_EQ(config.scale_source, "road");
  EXPECT_EQ(config.segmentation.model, "default");
  EXPECT_EQ(config.scale.filter.window, ScaleFilterOptions().window);
  EXPECT_EQ(config.pipeline.frontend.tracker.detector.type, DetectorType::kSift);
}

TEST(RunConfigYaml, ReadsGivenKeysAndKeepsTheOthers) {
  testing::TempDir dir;
  const std::string path =
      WriteFile(dir,
                "Camera:\n  h0: 1.5\nFrontend:\n  detector: orb\n"
                "Scale:\n  filter_gaussian_sigma: 3\n  vote_edge_visit: "
                "per_edge\nSegmentation:\n  schedule: every_frame\n  every: 2\n");
  RunConfig config;
  ReadRunConfig(path, &config);
  EXPECT_EQ(*config.camera.h0, 1.5);
  EXPECT_FALSE(config.camera.HasIntrinsics());
  EXPECT_EQ(config.pipeline.frontend.tracker.detector.type, DetectorType::kOrb);
  EXPECT_EQ(config.scale.filter.gaussian_sigma, 3.0);
  EXPECT_EQ(config.scale.depth_vote.edge_visit, DepthConsistencyVoteOptions::EdgeVisit::kPerEdge);
  EXPECT_EQ(config.segmentation.every, 2);
  EXPECT_EQ(config.pipeline.segmentation_schedule.mode, SegmentationScheduleMode::kEveryFrame);
  EXPECT_EQ(config.scale.filter.window, 5);
  // Reusing masks over k frames is the every-frame schedule's; with keyframes it is an error.
  const std::string both = WriteFile(dir, "Segmentation:\n  every: 2\n");
  RunConfig defaults;
  EXPECT_THROW(ReadRunConfig(both, &defaults), Error);
}

TEST(RunConfigYaml, WrittenConfigReadsBackToTheSameFile) {
  testing::TempDir dir;
  RunConfig config;
  config.camera.fx = 718.856;
  config.camera.fy = 718.856;
  config.camera.cx = 607.1928;
  config.camera.cy = 185.2157;
  config.camera.width = 1241;
  config.camera.height = 376;
  config.camera.h0 = 1.0 / 3.0;
  config.scale.ransac.inlier_threshold = 0.1 + 0.2;
  config.segmentation.model = "models/a b.yaml";
  config.pipeline.frontend.motion.refinement.loss = SampsonRefinementOptions::Loss::kCauchy;
  const std::string text = FormatRunConfig(config);
  const std::string path = WriteFile(dir, text);
  RunConfig back;
  ReadRunConfig(path, &back);
  EXPECT_EQ(FormatRunConfig(back), text);
  EXPECT_EQ(*back.camera.h0, 1.0 / 3.0);
  EXPECT_EQ(back.scale.ransac.inlier_threshold, 0.1 + 0.2);
  EXPECT_EQ(back.segmentation.model, "models/a b.yaml");
  EXPECT_EQ(*back.camera.width, 1241);
}

// config_used.yaml of a run through a distorting lens dropped the lens, so that repeating the
// run with it gave other poses (issue 30, defect 3).
TEST(RunConfigYaml, TheLensDistortionIsWrittenAndReadBack) {
  testing::TempDir dir;
  RunConfig config;
  config.camera.fx = 718.856;
  config.camera.fy = 718.856;
  config.camera.cx = 607.1928;
  config.camera.cy = 185.2157;
  config.camera.width = 1241;
  config.camera.height = 376;
  config.camera.SetDistortion({-0.3, 0.09, 0.0, 0.001, 1.0 / 3.0});
  const std::string text = FormatRunConfig(config);
  EXPECT_NE(text.find("  k1: -0.3\n  k2: 0.09\n  p1: 0\n  p2: 0.001\n  k3: 0.333"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("k4"), std::string::npos) << text;
  RunConfig back;
  ReadRunConfig(WriteFile(dir, text), &back);
  EXPECT_EQ(back.camera.Distortion(), (std::vector<double>{-0.3, 0.09, 0.0, 0.001, 1.0 / 3.0}));
  EXPECT_EQ(FormatRunConfig(back), text);

  RunConfig rational;
  ReadRunConfig(WriteFile(dir,
                          "Camera:\n  fx: 700\n  fy: 700\n  cx: 320\n  cy: 240\n"
                          "  width: 640\n  height: 480\n  k6: 0.01\n"),
                &rational);
  EXPECT_EQ(rational.camera.Distortion(), (std::vector<double>{0, 0, 0, 0, 0, 0, 0, 0.01}));
  RunConfig pinhole;
  pinhole.camera.SetDistortion({});
  EXPECT_TRUE(pinhole.camera.Distortion().empty());
  EXPECT_EQ(FormatRunConfig(pinhole), FormatRunConfig(RunConfig()));

  // A lens without the camera it belongs to is an error.
  EXPECT_EQ(ErrorOf(WriteFile(dir, "Camera:\n  k1: -0.3\n")),
            (dir.path() / "config.yaml").string() +
                ": Camera: the lens's k1..k6, p1, p2 go with fx, fy, cx, cy, width, height");
}

// config/kitti.yaml is the documented list of keys: it must hold every key the program
// writes, each with the program's default (the camera's intrinsics come from calib.txt).
TEST(RunConfigYaml, KittiConfigListsEveryKeyWithItsDefault) {
  RunConfig from_file;
  ReadRunConfig(std::string(ROADSCALE_SOURCE_DIR) + "/config/kitti.yaml", &from_file);
  RunConfig defaults;
  defaults.camera.h0 = 1.65;
  EXPECT_EQ(FormatRunConfig(from_file), FormatRunConfig(defaults));

  std::ifstream file(std::string(ROADSCALE_SOURCE_DIR) + "/config/kitti.yaml");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::istringstream written(FormatRunConfig(defaults));
  for (std::string line; std::getline(written, line);) {
    const size_t colon = line.find(':');
    const bool unset = line.size() >= 2 && line.compare(line.size() - 2, 2, " ~") == 0;
    if (line.rfind("  ", 0) != 0 || colon == std::string::npos || unset) continue;
    const std::string key = line.substr(0, colon + 1);
    EXPECT_NE(text.find("\n" + key), std::string::npos) << "config/kitti.yaml lacks" << key;
  }
}

TEST(RunConfigYaml, RealtimeConfigSegmentsEveryOtherFrameOnTwoThreads) {
  RunConfig config;
  ReadRunConfig(std::string(ROADSCALE_SOURCE_DIR) + "/config/kitti_realtime.yaml", &config);
  EXPECT_EQ(config.segmentation.every, 2);
  EXPECT_EQ(config.segmentation.dnn_threads, 2);
  config.segmentation.every = 1;
  config.segmentation.dnn_threads = 1;
  config.pipeline.segmentation_schedule.mode = SegmentationScheduleMode::kKeyframes;
  EXPECT_EQ(FormatRunConfig(config), FormatRunConfig(RunConfig()));
}

TEST(RunConfigYaml, ErrorsNameTheFileAndLine) {
  testing::TempDir dir;
  const std::string unknown_key = WriteFile(dir, "Scale:\n  use_filter: true\n  filtr: 1\n");
  EXPECT_NE(ErrorOf(unknown_key).find("config.yaml:3: unknown key 'Scale.filtr'"),
            std::string::npos)
      << ErrorOf(unknown_key);
  const std::string unknown_block = WriteFile(dir, "Backend:\n  x: 1\n");
  EXPECT_NE(ErrorOf(unknown_block).find("config.yaml:1: unknown block 'Backend'"),
            std::string::npos);
  const std::string wrong_type = WriteFile(dir, "Frontend:\n  min_inliers: lots\n");
  EXPECT_NE(ErrorOf(wrong_type).find("config.yaml:2: invalid value for Frontend.min_inliers"),
            std::string::npos);
  const std::string wrong_enum = WriteFile(dir, "Frontend:\n  detector: surf\n");
  EXPECT_NE(ErrorOf(wrong_enum).find("config.yaml:2:"), std::string::npos);
  const std::string partial_camera = WriteFile(dir, "Camera:\n  fx: 700\n");
  EXPECT_NE(ErrorOf(partial_camera).find("give all of fx, fy, cx, cy, width, height"),
            std::string::npos);
  EXPECT_NE(ErrorOf((dir.path() / "missing.yaml").string()).find("missing.yaml"),
            std::string::npos);
}

TEST(RunConfigYaml, RepeatedBlocksAndKeysAreErrors) {
  testing::TempDir dir;
  const std::string block_twice =
      WriteFile(dir,
                "Scale:\n  filter_window: 3\nFrontend:\n  detector: orb\nScale:\n  "
                "use_filter: false\n");
  EXPECT_NE(ErrorOf(block_twice)
                .find("config.yaml:5: key 'Scale' appears twice in one mapping (first on line 1)"),
            std::string::npos)
      << ErrorOf(block_twice);
  const std::string empty_key = WriteFile(dir, "Scale:\n  : 3\n");
  EXPECT_NE(ErrorOf(empty_key).find("config.yaml:2: a key is empty"), std::string::npos)
      << ErrorOf(empty_key);
  const std::string key_twice = WriteFile(dir, "Frontend:\n  detector: orb\n  detector: sift\n");
  EXPECT_NE(ErrorOf(key_twice).find("config.yaml:3: key 'detector' appears twice"),
            std::string::npos)
      << ErrorOf(key_twice);
}

TEST(RunConfigYaml, RangeErrorsNameTheFileAndTheKeysLine) {
  testing::TempDir dir;
  const std::string window = WriteFile(
      dir, "Frontend:\n  detector: orb\nScale:\n  use_filter: true\n  filter_window: -3\n");
  EXPECT_EQ(ErrorOf(window).rfind(
                dir.File("config.yaml") + ":5: Scale.filter_window: invalid option ", 0),
            0u)
      << ErrorOf(window);
  const std::string height = WriteFile(dir, "Camera:\n  h0: 1650\n");
  EXPECT_EQ(ErrorOf(height),
            dir.File("config.yaml") +
                ":2: Camera.h0: invalid option camera.h0: the camera height above the road must "
                "be in [0.05, 100] metres, got 1650");
  const std::string camera = WriteFile(
      dir, "Camera:\n  fx: 700\n  fy: 0\n  cx: 320\n  cy: 240\n  width: 640\n  height: 480\n");
  EXPECT_EQ(ErrorOf(camera).rfind(dir.File("config.yaml") + ":3: Camera.fy: invalid option ", 0),
            0u)
      << ErrorOf(camera);
  const std::string workers = WriteFile(dir, "Segmentation:\n  every: 1\n  workers: 99\n");
  EXPECT_EQ(ErrorOf(workers), dir.File("config.yaml") +
                                  ":3: Segmentation.workers: invalid option segmentation.workers: "
                                  "must be in [1, 16] (found 99)");
}

}  // namespace
}  // namespace roadscale
