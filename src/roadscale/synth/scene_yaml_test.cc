#include "roadscale/synth/scene_yaml.h"

#include <string>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale::synth {
namespace {

std::string ErrorOf(const std::string& preset, const std::string& path) {
  try {
    LoadSceneOptions(preset, path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SceneYaml, NoFileGivesThePreset) {
  EXPECT_EQ(LoadSceneOptions("", "").preset, "urban");
  const SceneOptions highway = LoadSceneOptions("highway", "");
  EXPECT_EQ(highway.road.lanes_same, 2);
  EXPECT_DOUBLE_EQ(highway.vehicle.speed_min, 24.0);
  EXPECT_THROW(LoadSceneOptions("mars", ""), Error);
}

TEST(SceneYaml, FileOverridesItsPresetAndTheCommandLinePresetWins) {
  testing::TempDir dir;
  const std::string path = testing::WriteTextFile(dir.File("scene.yaml"), R"(
preset: highway
seed: 42
Camera: {fx: 500, fy: 500, cx: 320, cy: 120, width: 640, height: 240, h0: 1.4}
Road:
  lanes_same: 3
  paved_ground: false
  pieces:
    - {length: 100}
    - {length: 50, radius: -40, grade: 0.03, bank_deg: 2, transition: 10}
    - {length: 50, curvature: 0.01}
Vehicle: {pitch_amplitude_deg: 0.7}
Texture: {shadows: no}
Image: {noise_sigma: 0, threads: 1}
)");
  const SceneOptions options = LoadSceneOptions("", path);
  EXPECT_EQ(options.preset, "highway");
  EXPECT_EQ(options.seed, 42u);
  EXPECT_EQ(options.road.lanes_same, 3);
  EXPECT_EQ(options.road.lanes_opposite, 2);  // from the preset
  EXPECT_FALSE(options.road.paved_ground);
  ASSERT_EQ(options.road.pieces.size(), 3u);
  EXPECT_DOUBLE_EQ(options.road.pieces[1].curvature, -1.0 / 40.0);
  EXPECT_NEAR(options.road.pieces[1].bank, 2.0 * M_PI / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(options.road.pieces[2].curvature, 0.01);
  EXPECT_DOUBLE_EQ(options.vehicle.pitch_amplitude_deg, 0.7);
  EXPECT_DOUBLE_EQ(options.vehicle.h0, 1.4);
  EXPECT_EQ(options.image.camera.width, 640);
  EXPECT_FALSE(options.texture.shadows);
  EXPECT_EQ(options.image.threads, 1);
  EXPECT_EQ(LoadSceneOptions("urban", path).preset, "urban");
  EXPECT_EQ(LoadSceneOptions("urban", path).road.lanes_same, 3);
}

TEST(SceneYaml, ErrorsNameTheFileTheLineAndTheKey) {
  testing::TempDir dir;
  const std::string unknown =
      testing::WriteTextFile(dir.File("a.yaml"), "Road:\n  lane_width: 3\n  lanes: 2\n");
  EXPECT_NE(ErrorOf("", unknown).find("a.yaml:3"), std::string::npos) << ErrorOf("", unknown);
  EXPECT_NE(ErrorOf("", unknown).find("Road.lanes"), std::string::npos);
  const std::string bad_number =
      testing::WriteTextFile(dir.File("b.yaml"), "Vehicle:\n  h0: tall\n");
  EXPECT_NE(ErrorOf("", bad_number).find("b.yaml:2"), std::string::npos);
  EXPECT_NE(ErrorOf("", bad_number).find("Vehicle.h0"), std::string::npos);
  const std::string bad_value = testing::WriteTextFile(dir.File("c.yaml"), "Vehicle:\n  h0: -2\n");
  EXPECT_NE(ErrorOf("", bad_value).find("Vehicle.h0"), std::string::npos);
  const std::string bad_block = testing::WriteTextFile(dir.File("d.yaml"), "Road: 3\n");
  EXPECT_NE(ErrorOf("", bad_block).find("Road: expected a mapping"), std::string::npos);
  const std::string both = testing::WriteTextFile(
      dir.File("e.yaml"), "Road:\n  pieces:\n    - {length: 9, radius: 20, curvature: 0.1}\n");
  EXPECT_NE(ErrorOf("", both).find("not both"), std::string::npos);
  const std::string broken = testing::WriteTextFile(dir.File("f.yaml"), "Road: [1, 2\n");
  EXPECT_NE(ErrorOf("", broken).find("f.yaml"), std::string::npos);
  EXPECT_NE(ErrorOf("", dir.File("missing.yaml")).find("cannot open"), std::string::npos);
}

TEST(SceneYaml, ShippedScenesParse) {
  const SceneOptions reference =
      LoadSceneOptions("", std::string(ROADSCALE_SOURCE_DIR) + "/config/synth/reference.yaml");
  const SceneOptions urban = PresetSceneOptions("urban");
  // The reference file lists the urban preset's values: spot-check every block.
  EXPECT_EQ(reference.road.sharp_radius_min, urban.road.sharp_radius_min);
  EXPECT_EQ(reference.vehicle.pitch_per_acceleration_deg, urban.vehicle.pitch_per_acceleration_deg);
  EXPECT_EQ(reference.traffic.oncoming_per_km, urban.traffic.oncoming_per_km);
  EXPECT_EQ(reference.scenery.wall_probability, urban.scenery.wall_probability);
  EXPECT_EQ(reference.texture.road_detail, urban.texture.road_detail);
  EXPECT_EQ(reference.image.haze_distance, urban.image.haze_distance);
  EXPECT_EQ(reference.image.camera.fx, urban.image.camera.fx);
  const SceneOptions twisty =
      LoadSceneOptions("", std::string(ROADSCALE_SOURCE_DIR) + "/config/synth/twisty_hills.yaml");
  EXPECT_EQ(twisty.preset, "hills");
  EXPECT_EQ(twisty.road.pieces.size(), 4u);
}

}  // namespace
}  // namespace roadscale::synth
