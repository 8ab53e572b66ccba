#include "roadscale/synth/scene_yaml.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>

#include <yaml-cpp/yaml.h>

#include "roadscale/geometry/angles.h"
#include "roadscale/util/error.h"
#include "roadscale/util/yaml_file.h"

namespace roadscale::synth {
namespace {

int LineOf(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

// Reads the keys of one mapping and complains about the ones nobody asked for.
class Block {
 public:
  Block(const YAML::Node& node, const std::string& path, const std::string& name)
      : node_(node), path_(path), name_(name) {
    if (!node.IsMap()) ThrowFileError(path, LineOf(node), name + ": expected a mapping");
  }

  bool Has(const char* key) const { return static_cast<bool>(node_[key]); }

  void Get(const char* key, double* value) {
    const YAML::Node node = Scalar(key);
    if (!node) return;
    const std::string& text = node.Scalar();
    char* end = nullptr;
    errno = 0;
    const double parsed = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
        !std::isfinite(parsed)) {
      Fail(node, key, "expected a number, found '" + text + "'");
    }
    *value = parsed;
  }

  void Get(const char* key, int* value) {
    double parsed = *value;
    Get(key, &parsed);
    if (parsed != std::floor(parsed) || std::abs(parsed) > 1e9) {
      Fail(node_[key], key, "expected an integer");
    }
    *value = static_cast<int>(parsed);
  }

  void Get(const char* key, bool* value) {
    const YAML::Node node = Scalar(key);
    if (!node) return;
    const std::string& text = node.Scalar();
    if (text == "true" || text == "yes" || text == "on") {
      *value = true;
    } else if (text == "false" || text == "no" || text == "off") {
      *value = false;
    } else {
      Fail(node, key, "expected true or false, found '" + text + "'");
    }
  }

  void Get(const char* key, uint64_t* value) {
    const YAML::Node node = Scalar(key);
    if (!node) return;
    const std::string& text = node.Scalar();
    char* end = nullptr;
    errno = 0;
    const unsigned long long parsed = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || end != text.c_str() + text.size() || errno == ERANGE) {
      Fail(node, key, "expected a non-negative integer, found '" + text + "'");
    }
    *value = parsed;
  }

  void Get(const char* key, std::string* value) {
    const YAML::Node node = Scalar(key);
    if (node) *value = node.Scalar();
  }

  YAML::Node Child(const char* key) {
    used_.insert(key);
    return node_[key];
  }

  // Throws for keys that no Get() asked for.
  void Finish() const {
    for (const auto& entry : node_) {
      const std::string key = entry.first.as<std::string>();
      if (used_.count(key) == 0) {
        ThrowFileError(path_, LineOf(entry.first),
                       "unknown key '" + (name_.empty() ? key : name_ + "." + key) + "'");
      }
    }
  }

  [[noreturn]] void Fail(const YAML::Node& node, const char* key,
                         const std::string& message) const {
    ThrowFileError(path_, LineOf(node),
                   (name_.empty() ? std::string(key) : name_ + "." + key) + ": " + message);
  }

 private:
  YAML::Node Scalar(const char* key) {
    used_.insert(key);
    const YAML::Node node = node_[key];
    if (!node) return node;
    if (!node.IsScalar()) Fail(node, key, "expected a single value");
    return node;
  }

  YAML::Node node_;
  std::string path_, name_;
  std::set<std::string> used_;
};

void ReadRoad(Block& b, RoadOptions* o, const std::string& path) {
  b.Get("lane_width", &o->lane_width);
  b.Get("lanes_same", &o->lanes_same);
  b.Get("lanes_opposite", &o->lanes_opposite);
  b.Get("parking_width", &o->parking_width);
  b.Get("shoulder_width", &o->shoulder_width);
  b.Get("median_width", &o->median_width);
  b.Get("kerb_height", &o->kerb_height);
  b.Get("sidewalk_width", &o->sidewalk_width);
  b.Get("verge_width", &o->verge_width);
  b.Get("ground_width", &o->ground_width);
  b.Get("paved_ground", &o->paved_ground);
  b.Get("crown_slope", &o->crown_slope);
  b.Get("straight_min", &o->straight_min);
  b.Get("straight_max", &o->straight_max);
  b.Get("radius_min", &o->radius_min);
  b.Get("radius_max", &o->radius_max);
  b.Get("curve_angle_min_deg", &o->curve_angle_min_deg);
  b.Get("curve_angle_max_deg", &o->curve_angle_max_deg);
  b.Get("sharp_turn_probability", &o->sharp_turn_probability);
  b.Get("sharp_radius_min", &o->sharp_radius_min);
  b.Get("sharp_radius_max", &o->sharp_radius_max);
  b.Get("sharp_angle_min_deg", &o->sharp_angle_min_deg);
  b.Get("sharp_angle_max_deg", &o->sharp_angle_max_deg);
  b.Get("grade_max", &o->grade_max);
  b.Get("grade_change_probability", &o->grade_change_probability);
  b.Get("bank_max_deg", &o->bank_max_deg);
  b.Get("transition", &o->transition);
  const YAML::Node pieces = b.Child("pieces");
  if (!pieces) return;
  if (!pieces.IsSequence()) ThrowFileError(path, LineOf(pieces), "Road.pieces: expected a list");
  o->pieces.clear();
  for (const YAML::Node& node : pieces) {
    Block piece_block(node, path, "Road.pieces");
    RoadPiece piece;
    double radius = 0.0, bank_deg = 0.0;
    piece_block.Get("length", &piece.length);
    if (!piece_block.Has("length")) piece_block.Fail(node, "length", "missing");
    if (piece_block.Has("radius") && piece_block.Has("curvature")) {
      piece_block.Fail(node, "radius", "give radius or curvature, not both");
    }
    piece_block.Get("radius", &radius);
    piece_block.Get("curvature", &piece.curvature);
    if (radius != 0.0) piece.curvature = 1.0 / radius;
    piece_block.Get("grade", &piece.grade);
    piece_block.Get("bank_deg", &bank_deg);
    piece.bank = bank_deg * kRadiansPerDegree;
    piece_block.Get("transition", &piece.transition);
    piece_block.Finish();
    o->pieces.push_back(piece);
  }
}

void ReadVehicle(Block& b, VehicleOptions* o) {
  b.Get("h0", &o->h0);
  b.Get("camera_pitch_deg", &o->camera_pitch_deg);
  b.Get("camera_roll_deg", &o->camera_roll_deg);
  b.Get("camera_ahead", &o->camera_ahead);
  b.Get("initial_speed", &o->initial_speed);
  b.Get("speed_min", &o->speed_min);
  b.Get("speed_max", &o->speed_max);
  b.Get("cruise_min_s", &o->cruise_min_s);
  b.Get("cruise_max_s", &o->cruise_max_s);
  b.Get("stop_probability", &o->stop_probability);
  b.Get("stop_min_s", &o->stop_min_s);
  b.Get("stop_max_s", &o->stop_max_s);
  b.Get("acceleration", &o->acceleration);
  b.Get("deceleration", &o->deceleration);
  b.Get("pitch_amplitude_deg", &o->pitch_amplitude_deg);
  b.Get("pitch_frequency_hz", &o->pitch_frequency_hz);
  b.Get("roll_amplitude_deg", &o->roll_amplitude_deg);
  b.Get("roll_frequency_hz", &o->roll_frequency_hz);
  b.Get("suspension_speed", &o->suspension_speed);
  b.Get("bumps_per_km", &o->bumps_per_km);
  b.Get("bump_pitch_deg", &o->bump_pitch_deg);
  b.Get("bump_damping", &o->bump_damping);
  b.Get("bump_frequency_hz", &o->bump_frequency_hz);
  b.Get("pitch_per_acceleration_deg", &o->pitch_per_acceleration_deg);
  b.Get("start_position", &o->start_position);
}

void ReadTraffic(Block& b, TrafficOptions* o) {
  b.Get("parked_fraction", &o->parked_fraction);
  b.Get("lead_car", &o->lead_car);
  b.Get("lead_gap_min", &o->lead_gap_min);
  b.Get("lead_gap_max", &o->lead_gap_max);
  b.Get("oncoming_per_km", &o->oncoming_per_km);
  b.Get("same_direction_per_km", &o->same_direction_per_km);
  b.Get("overtaking_per_km", &o->overtaking_per_km);
  b.Get("car_speed_min", &o->car_speed_min);
  b.Get("car_speed_max", &o->car_speed_max);
  b.Get("pedestrians_per_100m", &o->pedestrians_per_100m);
}

void ReadScenery(Block& b, SceneryOptions* o) {
  b.Get("building_fraction", &o->building_fraction);
  b.Get("building_setback_min", &o->building_setback_min);
  b.Get("building_setback_max", &o->building_setback_max);
  b.Get("building_height_min", &o->building_height_min);
  b.Get("building_height_max", &o->building_height_max);
  b.Get("building_width_min", &o->building_width_min);
  b.Get("building_width_max", &o->building_width_max);
  b.Get("tree_spacing", &o->tree_spacing);
  b.Get("tree_probability", &o->tree_probability);
  b.Get("pole_spacing", &o->pole_spacing);
  b.Get("wall_probability", &o->wall_probability);
  b.Get("vegetation_probability", &o->vegetation_probability);
  b.Get("backdrop_trees", &o->backdrop_trees);
}

void ReadTexture(Block& b, TextureOptions* o) {
  b.Get("road_contrast", &o->road_contrast);
  b.Get("road_detail", &o->road_detail);
  b.Get("facade_contrast", &o->facade_contrast);
  b.Get("vegetation_contrast", &o->vegetation_contrast);
  b.Get("shadows", &o->shadows);
}

void ReadLabels(Block& b, LabelErrorOptions* o) {
  b.Get("dynamic_erosion_px", &o->dynamic_erosion_px);
  b.Get("dynamic_lag_frames", &o->dynamic_lag_frames);
  b.Get("dynamic_dropout", &o->dynamic_dropout);
}

void ReadImage(Block& b, ImageOptions* o) {
  b.Get("frame_rate", &o->frame_rate);
  b.Get("noise_sigma", &o->noise_sigma);
  b.Get("exposure_variation", &o->exposure_variation);
  b.Get("exposure_period_s", &o->exposure_period_s);
  b.Get("sun_elevation_deg", &o->sun_elevation_deg);
  b.Get("sun_azimuth_deg", &o->sun_azimuth_deg);
  b.Get("ambient", &o->ambient);
  b.Get("haze_distance", &o->haze_distance);
  b.Get("far_distance", &o->far_distance);
  b.Get("threads", &o->threads);
}

void ReadCamera(Block& b, PinholeCamera* camera, double* h0) {
  b.Get("fx", &camera->fx);
  b.Get("fy", &camera->fy);
  b.Get("cx", &camera->cx);
  b.Get("cy", &camera->cy);
  b.Get("width", &camera->width);
  b.Get("height", &camera->height);
  b.Get("h0", h0);
}

}  // namespace

SceneOptions LoadSceneOptions(const std::string& preset, const std::string& yaml_path) {
  if (yaml_path.empty()) {
    SceneOptions options = PresetSceneOptions(preset.empty() ? "urban" : preset);
    options.Check();
    return options;
  }
  YAML::Node root = LoadYamlFile(yaml_path, "scene file");
  if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  Block top(root, yaml_path, "");
  std::string file_preset;
  top.Get("preset", &file_preset);
  SceneOptions options =
      PresetSceneOptions(!preset.empty() ? preset : (file_preset.empty() ? "urban" : file_preset));
  top.Get("seed", &options.seed);
  struct Section {
    const char* name;
    void (*read)(Block&, SceneOptions*, const std::string&);
  };
  static const Section kSections[] = {
      {"Road", [](Block& b, SceneOptions* o, const std::string& p) { ReadRoad(b, &o->road, p); }},
      {"Vehicle",
       [](Block& b, SceneOptions* o, const std::string&) { ReadVehicle(b, &o->vehicle); }},
      {"Traffic",
       [](Block& b, SceneOptions* o, const std::string&) { ReadTraffic(b, &o->traffic); }},
      {"Scenery",
       [](Block& b, SceneOptions* o, const std::string&) { ReadScenery(b, &o->scenery); }},
      {"Texture",
       [](Block& b, SceneOptions* o, const std::string&) { ReadTexture(b, &o->texture); }},
      {"Image", [](Block& b, SceneOptions* o, const std::string&) { ReadImage(b, &o->image); }},
      {"Labels", [](Block& b, SceneOptions* o, const std::string&) { ReadLabels(b, &o->labels); }},
      {"Camera", [](Block& b, SceneOptions* o,
                    const std::string&) { ReadCamera(b, &o->image.camera, &o->vehicle.h0); }},
  };
  for (const Section& section : kSections) {
    const YAML::Node node = top.Child(section.name);
    if (!node) continue;
    Block block(node, yaml_path, section.name);
    section.read(block, &options, yaml_path);
    block.Finish();
  }
  top.Finish();
  try {
    options.Check();
  } catch (const Error& e) {
    ThrowFileError(yaml_path, e.what());
  }
  return options;
}

}  // namespace roadscale::synth
