#include "roadscale/config/config_yaml.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "roadscale/geometry/camera_height.h"
#include "roadscale/geometry/field_of_view.h"
#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/yaml_file.h"

namespace roadscale {
namespace {

// One key of the file: how to read it from a node, how to write the current value.
struct Key {
  std::string name;
  std::function<void(const YAML::Node&)> read;  // throws YAML::Exception on a wrong type
  std::function<std::string()> write;
};

struct Block {
  std::string name;
  std::vector<Key> keys;
};

// The shortest of 15..17 significant digits that reads back to the same double.
std::string FormatDouble(double value) {
  for (int digits = 15;; ++digits) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    if (digits == 17 || std::strtod(out.str().c_str(), nullptr) == value) return out.str();
  }
}

template <typename T>
Key Scalar(const std::string& name, T* value) {
  return {name, [value](const YAML::Node& node) { *value = node.as<T>(); },
          [value] {
            if constexpr (std::is_same_v<T, double>) {
              return FormatDouble(*value);
            } else if constexpr (std::is_same_v<T, bool>) {
              return std::string(*value ? "true" : "false");
            } else if constexpr (std::is_same_v<T, std::string>) {
              return YAML::Dump(YAML::Node(*value));
            } else {
              return std::to_string(*value);
            }
          }};
}

template <typename T>
Key Optional(const std::string& name, std::optional<T>* value) {
  return {name, [value](const YAML::Node& node) { *value = node.as<T>(); },
          [value] {
            if (!value->has_value()) return std::string("~");
            if constexpr (std::is_same_v<T, double>) return FormatDouble(**value);
            return std::to_string(**value);
          }};
}

// An enum written as one of `names` (index = the enum's value).
template <typename E>
Key Enum(const std::string& name, E* value, std::vector<std::string> names) {
  return {name,
          [value, names, name](const YAML::Node& node) {
            const std::string text = node.as<std::string>();
            for (size_t i = 0; i < names.size(); ++i) {
              if (names[i] == text) {
                *value = static_cast<E>(i);
                return;
              }
            }
            std::string expected;
            for (const std::string& n : names) expected += (expected.empty() ? "" : ", ") + n;
            throw YAML::Exception(node.Mark(), name + ": '" + text + "' is not one of " + expected);
          },
          [value, names] { return names[static_cast<size_t>(*value)]; }};
}

std::vector<Block> Blocks(RunConfig& c) {
  FrontendOptions& f = c.pipeline.frontend;
  FeatureDetectorOptions& d = f.tracker.detector;
  KltOptions& k = f.tracker.klt;
  TwoViewMotionOptions& m = f.motion;
  ScaleEstimatorOptions& s = c.scale;
  SegmentationOptions& g = c.segmentation;
  MappingOptions& a = c.pipeline.mapping;
  return {
      {"Camera",
       {Optional("fx", &c.camera.fx), Optional("fy", &c.camera.fy), Optional("cx", &c.camera.cx),
        Optional("cy", &c.camera.cy), Optional("width", &c.camera.width),
        Optional("height", &c.camera.height), Optional("h0", &c.camera.h0),
        Optional("k1", &c.camera.distortion[0]), Optional("k2", &c.camera.distortion[1]),
        Optional("p1", &c.camera.distortion[2]), Optional("p2", &c.camera.distortion[3]),
        Optional("k3", &c.camera.distortion[4]), Optional("k4", &c.camera.distortion[5]),
        Optional("k5", &c.camera.distortion[6]), Optional("k6", &c.camera.distortion[7])}},
      {"Frontend",
       {Enum("detector", &d.type, {"sift", "orb", "brisk", "akaze", "fast"}),
        Scalar("cell_size_px", &d.cell_size_px),
        Scalar("max_per_cell", &d.max_per_cell),
        Scalar("road_max_per_cell", &d.road_max_per_cell),
        Scalar("min_distance_px", &d.min_distance_px),
        Scalar("sift_half_resolution", &d.sift_half_resolution),
        Scalar("border_px", &d.border_px),
        Scalar("sift_contrast_threshold", &d.sift_contrast_threshold),
        Scalar("corner_threshold", &d.corner_threshold),
        Scalar("redetect_below", &f.tracker.redetect_below),
        Scalar("klt_window_size", &k.window_size),
        Scalar("klt_pyramid_levels", &k.pyramid_levels),
        Scalar("klt_max_iterations", &k.max_iterations),
        Scalar("klt_epsilon", &k.epsilon),
        Scalar("klt_min_eigen_threshold", &k.min_eigen_threshold),
        Scalar("klt_max_forward_backward_error_px", &k.max_forward_backward_error_px),
        Scalar("klt_backward_pyramid_levels", &k.backward_pyramid_levels),
        Scalar("predict_with_rotation", &f.predict_with_rotation),
        Scalar("drop_outliers", &f.drop_outliers),
        Scalar("ransac_threshold_px", &m.ransac_threshold_px),
        Scalar("ransac_confidence", &m.ransac_confidence),
        Scalar("ransac_max_iterations", &m.ransac_max_iterations),
        Scalar("seed", &m.seed),
        Scalar("min_correspondences", &m.min_correspondences),
        Scalar("min_inliers", &m.min_inliers),
        Scalar("min_inlier_ratio", &m.min_inlier_ratio),
        Scalar("stationary_flow_px", &m.stationary_flow_px),
        Scalar("min_parallax_px", &m.min_parallax_px),
        Scalar("refine", &m.refine),
        Scalar("refinement_inlier_sigmas", &m.refinement_inlier_sigmas),
        Scalar("refinement_epipole_exclusion_deg", &m.refinement_epipole_exclusion_deg),
        Scalar("refinement_max_iterations", &m.refinement.max_iterations),
        Enum("refinement_loss", &m.refinement.loss, {"huber", "cauchy"}),
        Scalar("refinement_loss_scale_px", &m.refinement.loss_scale_px),
        Scalar("refinement_relative_tolerance", &m.refinement.relative_tolerance)}},
      {"Scale",
       {Scalar("source", &c.scale_source),
        Scalar("use_segmentation", &s.use_segmentation),
        Scalar("use_horizon", &s.use_horizon),
        Scalar("use_depth_vote", &s.use_depth_vote),
        Scalar("use_road_model_check", &s.use_road_model_check),
        Scalar("use_filter", &s.use_filter),
        Scalar("homography_refit", &s.homography_refit),
        Scalar("homography_refine_rotation", &s.homography.refine_rotation),
        Scalar("homography_tangent_to_travel", &s.homography.tangent_to_travel),
        Scalar("homography_travel_prior_px_per_deg", &s.homography.travel_prior_px_per_deg),
        Scalar("homography_loss_scale_px", &s.homography.loss_scale_px),
        Scalar("homography_max_iterations", &s.homography.max_iterations),
        Scalar("min_parallax_deg", &s.triangulation.min_parallax_deg),
        Scalar("max_reprojection_error_px", &s.triangulation.max_reprojection_error_px),
        Enum("vote_edge_visit", &s.depth_vote.edge_visit, {"per_triangle", "per_edge"}),
        Scalar("vote_min_vote", &s.depth_vote.min_vote),
        Enum("road_model_reference", &s.road_model.reference, {"motion", "fixed_pitch"}),
        Scalar("road_model_camera_pitch_deg", &s.road_model.camera_pitch_deg),
        Scalar("road_model_max_angle_deg", &s.road_model.max_angle_deg),
        Scalar("ransac_min_points", &s.ransac.min_points),
        Scalar("ransac_inlier_threshold", &s.ransac.inlier_threshold),
        Scalar("ransac_max_iterations", &s.ransac.max_iterations),
        Scalar("ransac_confidence", &s.ransac.confidence),
        Scalar("ransac_seed", &s.ransac.seed),
        Scalar("ransac_max_tilt_deg", &s.ransac.max_tilt_deg),
        Scalar("filter_window", &s.filter.window),
        Scalar("filter_gaussian_sigma", &s.filter.gaussian_sigma),
        Scalar("filter_max_change_per_frame", &s.filter.max_change_per_frame),
        Scalar("max_frames_before_first_scale", &c.pipeline.max_frames_before_first_scale)}},
      {"Mapping",
       {Enum("mode", &a.mode, {"keyframe", "frame_to_frame"}),
        Scalar("window_size", &a.window_size),
        Scalar("keyframe_min_parallax_px", &a.keyframes.min_parallax_px),
        Scalar("keyframe_min_tracked_share", &a.keyframes.min_tracked_share),
        Scalar("keyframe_max_frame_gap", &a.keyframes.max_frame_gap),
        Scalar("landmark_min_parallax_deg", &a.landmarks.min_parallax_deg),
        Scalar("landmark_max_reprojection_error_px", &a.landmarks.max_reprojection_error_px),
        Scalar("landmark_max_depth_below_ground", &a.landmarks.max_depth_below_ground),
        Scalar("road_min_points_per_pair", &a.road_min_points_per_pair),
        Scalar("road_pool_pairs", &a.road_pool_pairs),
        Scalar("road_max_height_ratio", &a.road_max_height_ratio),
        Scalar("first_scale_max_speed", &a.first_scale_max_speed),
        Scalar("fallback_to_pair_fixes", &a.fallback_to_pair_fixes),
        Scalar("road_alignment", &a.road_alignment),
        Scalar("road_alignment_levels", &a.alignment.pyramid_levels),
        Scalar("road_alignment_min_gradient", &a.alignment.min_gradient),
        Scalar("road_alignment_max_samples", &a.alignment.max_samples),
        Scalar("road_alignment_min_samples", &a.alignment.min_samples),
        Scalar("road_alignment_max_iterations", &a.alignment.max_iterations),
        Scalar("road_alignment_loss_grey", &a.alignment.loss_scale_grey),
        Scalar("road_alignment_search_factor", &a.alignment.expected_search_factor),
        Scalar("road_alignment_mask_erosion_px", &a.alignment.mask_erosion_px),
        Scalar("road_alignment_max_lateral", &a.alignment.max_lateral_offset),
        Scalar("road_alignment_max_distance", &a.alignment.max_distance),
        Scalar("road_alignment_tangent_to_travel", &a.alignment.tangent_to_travel),
        Scalar("road_alignment_max_pitch_to_travel", &a.alignment.max_pitch_to_travel_deg),
        Scalar("road_alignment_shadow_brightness", &a.road_alignment_shadow_brightness),
        Scalar("road_alignment_region_distance", &a.road_region_max_distance),
        Scalar("road_alignment_region_half_width", &a.road_region_half_width),
        Scalar("localization_min_landmarks", &a.localization.min_landmarks),
        Scalar("localization_loss_px", &a.localization.loss_px),
        Scalar("localization_max_iterations", &a.localization.max_iterations),
        Scalar("localization_inlier_threshold_px", &a.localization.inlier_threshold_px),
        Scalar("localization_min_inlier_ratio", &a.localization.min_inlier_ratio),
        Scalar("localization_ransac_iterations", &a.localization.ransac_iterations),
        Scalar("localization_max_direction_deg", &a.localization.max_direction_change_deg),
        Scalar("ba_max_iterations", &a.bundle_adjustment.max_iterations),
        Scalar("ba_reprojection_loss_px", &a.bundle_adjustment.reprojection_loss_px),
        Scalar("ba_max_reprojection_error_px", &a.bundle_adjustment.max_reprojection_error_px),
        Scalar("camera_height_sigma_m", &a.bundle_adjustment.camera_height_sigma_m),
        Scalar("camera_height_loss", &a.bundle_adjustment.camera_height_loss),
        Scalar("min_road_landmarks", &a.bundle_adjustment.min_road_landmarks),
        Scalar("road_outlier_sigmas", &a.bundle_adjustment.road_outlier_sigmas),
        Scalar("road_pair_sigma_m", &a.bundle_adjustment.road_pair_sigma_m)}},
      {"Segmentation",
       {Scalar("model", &g.model), Scalar("labels", &c.labels),
        Enum("schedule", &c.pipeline.segmentation_schedule.mode, {"every_frame", "keyframes"}),
        Scalar("latency_frames", &c.pipeline.segmentation_schedule.latency_frames),
        Scalar("min_carried_road_share", &c.pipeline.segmentation_schedule.min_carried_road_share),
        Scalar("keyframe_min_parallax_px",
               &c.pipeline.segmentation_schedule.keyframes.min_parallax_px),
        Scalar("keyframe_min_tracked_share",
               &c.pipeline.segmentation_schedule.keyframes.min_tracked_share),
        Scalar("keyframe_max_frame_gap", &c.pipeline.segmentation_schedule.keyframes.max_frame_gap),
        Scalar("carry_road_min_tracks", &c.pipeline.segmentation_schedule.carry.road_min_tracks),
        Scalar("carry_road_ransac_threshold_px",
               &c.pipeline.segmentation_schedule.carry.road_ransac_threshold_px),
        Scalar("carry_dynamic_growth_px_per_frame",
               &c.pipeline.segmentation_schedule.carry.dynamic_growth_px_per_frame),
        Scalar("carry_road_on_motion", &c.pipeline.segmentation_schedule.carry.road_on_motion),
        Scalar("carry_dynamic_in_place", &c.pipeline.segmentation_schedule.carry.dynamic_in_place),
        Scalar("every", &g.every), Scalar("dnn_threads", &g.dnn_threads),
        Scalar("workers", &g.workers), Scalar("use_dynamic_mask", &g.masks.use_dynamic_mask),
        Scalar("dynamic_dilation_px", &g.masks.dynamic_dilation_px),
        Scalar("road_erosion_px", &g.masks.road_erosion_px)}},
  };
}

[[noreturn]] void ThrowAt(const std::string& path, const YAML::Mark& mark,
                          const std::string& message) {
  if (mark.is_null()) ThrowFileError(path, message);
  throw Error(path + ":" + std::to_string(mark.line + 1) + ": " + message);
}

// A key as the file gave it, to read it again onto another config.
struct ReadKey {
  std::string block;
  std::string key;
  YAML::Node value;
};

RunConfig ApplyAllBut(const RunConfig& initial, const std::vector<ReadKey>& keys, size_t skip) {
  RunConfig trial = initial;
  std::vector<Block> blocks = Blocks(trial);
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i == skip) continue;
    for (const Block& block : blocks) {
      for (const Key& key : block.keys) {
        if (block.name == keys[i].block && key.name == keys[i].key) key.read(keys[i].value);
      }
    }
  }
  return trial;
}

void CheckValues(const RunConfig& config) {
  if (config.camera.h0) CheckCameraHeight(*config.camera.h0, "camera.h0");
  // Each intrinsic on its own (with its image side), so that leaving out the bad one is what
  // makes the config pass.
  const RunConfig::Camera& camera = config.camera;
  for (const auto& [focal, name] : {std::pair{camera.fx, "camera.fx"}, {camera.fy, "camera.fy"}}) {
    if (focal) CheckOption(std::isfinite(*focal) && *focal > 0.0, name, "must be positive");
  }
  for (const std::optional<double>& coefficient : camera.distortion) {
    if (coefficient) {
      CheckOption(std::isfinite(*coefficient), "camera.distortion", "coefficients must be finite");
    }
  }
  for (const auto& [side, name] :
       {std::pair{camera.width, "camera.width"}, {camera.height, "camera.height"}}) {
    if (side) CheckOption(*side > 0, name, "must be positive");
  }
  for (const auto& [focal, side, name] : {std::tuple{camera.fx, camera.width, "camera.fx"},
                                          {camera.fy, camera.height, "camera.fy"}}) {
    if (focal && side && *side > 0) CheckFocalLength(*focal, *side, name);
  }
  for (const auto& [centre, side, name] : {std::tuple{camera.cx, camera.width, "camera.cx"},
                                           {camera.cy, camera.height, "camera.cy"}}) {
    if (centre && side) {
      CheckOption(*centre >= 0.0 && *centre <= *side, name, "must lie inside the image");
    }
  }
  config.pipeline.Check();
  config.scale.Check();
  config.segmentation.Check();
  CheckOption(config.segmentation.every == 1 || config.pipeline.segmentation_schedule.mode ==
                                                    SegmentationScheduleMode::kEveryFrame,
              "segmentation.every", "reuses masks only with schedule: every_frame");
}

// The options' range checks, with the file and the culprit key's line: the first key without
// which the config passes (when only several keys together break a check, the file alone).
void CheckConfigValues(const std::string& path, const RunConfig& initial,
                       const std::vector<ReadKey>& keys, const RunConfig& config) {
  try {
    CheckValues(config);
  } catch (const Error& error) {
    for (size_t i = 0; i < keys.size(); ++i) {
      try {
        CheckValues(ApplyAllBut(initial, keys, i));
      } catch (const Error&) {
        continue;
      }
      // The value found, unless the check's message already ends with it ("..., got 1650").
      const YAML::Node& value = keys[i].value;
      const std::string what = error.what();
      const std::string text = value.IsScalar() ? value.Scalar() : "";
      const bool said = what.size() >= text.size() &&
                        what.compare(what.size() - text.size(), text.size(), text) == 0;
      const std::string found = said ? "" : " (found " + text + ")";
      ThrowAt(path, value.Mark(), keys[i].block + "." + keys[i].key + ": " + what + found);
    }
    ThrowFileError(path, error.what());
  }
}

std::string KeyNames(const Block& block) {
  std::string names;
  for (const Key& key : block.keys) names += (names.empty() ? "" : ", ") + key.name;
  return names;
}

}  // namespace

std::vector<double> RunConfig::Camera::Distortion() const {
  size_t used = 0;
  for (size_t i = 0; i < distortion.size(); ++i) {
    if (distortion[i]) used = i < 5 ? std::max<size_t>(used, 5) : 8;
  }
  std::vector<double> coefficients(used, 0.0);
  for (size_t i = 0; i < used; ++i) coefficients[i] = distortion[i].value_or(0.0);
  return coefficients;
}

void RunConfig::Camera::SetDistortion(const std::vector<double>& coefficients) {
  for (size_t i = 0; i < distortion.size(); ++i) {
    distortion[i] = i < coefficients.size() ? std::optional<double>(coefficients[i]) : std::nullopt;
  }
}

void ReadRunConfig(const std::string& path, RunConfig* config) {
  const YAML::Node root = LoadYamlFile(path, "config file");
  if (root.IsNull()) return;
  const RunConfig initial = *config;
  std::vector<ReadKey> read_keys;
  if (!root.IsMap())
    ThrowAt(path, root.Mark(),
            "expected blocks Camera:, Frontend:, Scale:, Mapping:, Segmentation:");
  std::vector<Block> blocks = Blocks(*config);
  for (const auto& entry : root) {
    const std::string block_name = entry.first.as<std::string>();
    Block* block = nullptr;
    for (Block& b : blocks) {
      if (b.name == block_name) block = &b;
    }
    if (block == nullptr) {
      ThrowAt(path, entry.first.Mark(),
              "unknown block '" + block_name +
                  "' (expected Camera, Frontend, Scale, Mapping or Segmentation)");
    }
    if (entry.second.IsNull()) continue;
    if (!entry.second.IsMap())
      ThrowAt(path, entry.second.Mark(), block_name + ": expected a mapping of keys");
    for (const auto& item : entry.second) {
      const std::string key_name = item.first.as<std::string>();
      const Key* key = nullptr;
      for (const Key& k : block->keys) {
        if (k.name == key_name) key = &k;
      }
      if (key == nullptr) {
        ThrowAt(path, item.first.Mark(),
                "unknown key '" + block_name + "." + key_name + "' (expected one of " +
                    KeyNames(*block) + ")");
      }
      try {
        if (item.second.IsNull()) {
          ThrowAt(path, item.second.Mark(), block_name + "." + key_name + " has no value");
        }
        key->read(item.second);
        read_keys.push_back({block_name, key_name, item.second});
      } catch (const YAML::Exception& e) {
        ThrowAt(path, item.second.Mark(),
                "invalid value for " + block_name + "." + key_name +
                    (e.msg.find(':') != std::string::npos ? " (" + e.msg + ")" : std::string()));
      }
    }
  }
  const RunConfig::Camera& camera = config->camera;
  const int given = camera.fx.has_value() + camera.fy.has_value() + camera.cx.has_value() +
                    camera.cy.has_value() + camera.width.has_value() + camera.height.has_value();
  if (given != 0 && given != 6) {
    ThrowFileError(path, "Camera: give all of fx, fy, cx, cy, width, height, or none");
  }
  if (given == 0 && !config->camera.Distortion().empty()) {
    ThrowFileError(path, "Camera: the lens's k1..k6, p1, p2 go with fx, fy, cx, cy, width, height");
  }
  CheckConfigValues(path, initial, read_keys, *config);
}

std::string FormatRunConfig(const RunConfig& config) {
  RunConfig copy = config;
  std::ostringstream out;
  out << "# Every option of this run (roadscale run --config THIS_FILE repeats it).\n";
  for (const Block& block : Blocks(copy)) {
    out << block.name << ":\n";
    for (const Key& key : block.keys) {
      const std::string value = key.write();
      if (value == "~") continue;  // an optional key without a value
      out << "  " << key.name << ": " << value << '\n';
    }
  }
  return out.str();
}

void WriteRunConfig(const std::string& path, const RunConfig& config) {
  WriteFileAtomically(path, FormatRunConfig(config));
}

}  // namespace roadscale
