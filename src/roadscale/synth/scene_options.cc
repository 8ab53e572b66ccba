#include "roadscale/synth/scene_options.h"

#include <cmath>

#include "roadscale/util/error.h"

namespace roadscale::synth {
namespace {

void CheckNonNegative(double value, const char* name) {
  CheckOption(std::isfinite(value) && value >= 0.0, name, "must be a non-negative number");
}

void CheckPositive(double value, const char* name) {
  CheckOption(std::isfinite(value) && value > 0.0, name, "must be a positive number");
}

void CheckRange(double low, double high, const char* name) {
  CheckOption(std::isfinite(low) && std::isfinite(high) && low <= high, name, "needs min <= max");
}

void CheckProbability(double value, const char* name) {
  CheckOption(std::isfinite(value) && value >= 0.0 && value <= 1.0, name, "must lie in [0, 1]");
}

}  // namespace

void RoadOptions::Check() const {
  CheckPositive(lane_width, "Road.lane_width");
  CheckOption(lanes_same >= 1 && lanes_same <= 4, "Road.lanes_same", "must be 1..4");
  CheckOption(lanes_opposite >= 0 && lanes_opposite <= 4, "Road.lanes_opposite", "must be 0..4");
  CheckNonNegative(parking_width, "Road.parking_width");
  CheckNonNegative(shoulder_width, "Road.shoulder_width");
  CheckNonNegative(median_width, "Road.median_width");
  CheckOption(std::isfinite(kerb_height) && kerb_height >= 0.0 && kerb_height <= 0.5,
              "Road.kerb_height", "must lie in [0, 0.5] m");
  CheckNonNegative(sidewalk_width, "Road.sidewalk_width");
  CheckNonNegative(verge_width, "Road.verge_width");
  CheckNonNegative(ground_width, "Road.ground_width");
  CheckOption(std::isfinite(crown_slope) && crown_slope >= 0.0 && crown_slope <= 0.08,
              "Road.crown_slope", "must lie in [0, 0.08]");
  CheckPositive(straight_min, "Road.straight_min");
  CheckRange(straight_min, straight_max, "Road.straight_min/max");
  CheckPositive(radius_min, "Road.radius_min");
  CheckRange(radius_min, radius_max, "Road.radius_min/max");
  CheckRange(curve_angle_min_deg, curve_angle_max_deg, "Road.curve_angle_min/max_deg");
  CheckProbability(sharp_turn_probability, "Road.sharp_turn_probability");
  CheckOption(sharp_radius_min >= 10.0, "Road.sharp_radius_min",
              "must be at least 10 m (the roadside would fold over itself)");
  CheckRange(sharp_radius_min, sharp_radius_max, "Road.sharp_radius_min/max");
  CheckRange(sharp_angle_min_deg, sharp_angle_max_deg, "Road.sharp_angle_min/max_deg");
  CheckOption(std::isfinite(grade_max) && grade_max >= 0.0 && grade_max <= 0.15, "Road.grade_max",
              "must lie in [0, 0.15]");
  CheckProbability(grade_change_probability, "Road.grade_change_probability");
  CheckOption(std::isfinite(bank_max_deg) && bank_max_deg >= 0.0 && bank_max_deg <= 10.0,
              "Road.bank_max_deg", "must lie in [0, 10]");
  CheckNonNegative(transition, "Road.transition");
  for (const RoadPiece& piece : pieces) {
    CheckPositive(piece.length, "Road.pieces.length");
    CheckNonNegative(piece.transition, "Road.pieces.transition");
    CheckOption(std::isfinite(piece.curvature) && std::abs(piece.curvature) <= 0.1,
                "Road.pieces.curvature",
                "must be a number with |curvature| <= 0.1 (radius >= 10 m)");
    CheckOption(std::isfinite(piece.grade) && std::abs(piece.grade) <= 0.15, "Road.pieces.grade",
                "must lie in [-0.15, 0.15]");
    CheckOption(std::isfinite(piece.bank) && std::abs(piece.bank) <= 0.2, "Road.pieces.bank_deg",
                "must lie in [-11, 11] degrees");
  }
}

void VehicleOptions::Check() const {
  CheckPositive(h0, "Vehicle.h0");
  CheckOption(std::abs(camera_pitch_deg) <= 30.0, "Vehicle.camera_pitch_deg",
              "must lie in [-30, 30]");
  CheckOption(std::abs(camera_roll_deg) <= 30.0, "Vehicle.camera_roll_deg",
              "must lie in [-30, 30]");
  CheckOption(std::isfinite(camera_ahead) && camera_ahead >= 0.0 && camera_ahead <= 5.0,
              "Vehicle.camera_ahead", "must lie in [0, 5] metres");
  CheckNonNegative(initial_speed, "Vehicle.initial_speed");
  CheckNonNegative(speed_min, "Vehicle.speed_min");
  CheckRange(speed_min, speed_max, "Vehicle.speed_min/max");
  CheckPositive(cruise_min_s, "Vehicle.cruise_min_s");
  CheckRange(cruise_min_s, cruise_max_s, "Vehicle.cruise_min/max_s");
  CheckProbability(stop_probability, "Vehicle.stop_probability");
  CheckPositive(stop_min_s, "Vehicle.stop_min_s");
  CheckRange(stop_min_s, stop_max_s, "Vehicle.stop_min/max_s");
  CheckPositive(acceleration, "Vehicle.acceleration");
  CheckPositive(deceleration, "Vehicle.deceleration");
  CheckOption(std::abs(pitch_amplitude_deg) <= 10.0, "Vehicle.pitch_amplitude_deg",
              "must lie in [-10, 10]");
  CheckOption(std::abs(roll_amplitude_deg) <= 10.0, "Vehicle.roll_amplitude_deg",
              "must lie in [-10, 10]");
  CheckNonNegative(pitch_frequency_hz, "Vehicle.pitch_frequency_hz");
  CheckNonNegative(roll_frequency_hz, "Vehicle.roll_frequency_hz");
  CheckPositive(suspension_speed, "Vehicle.suspension_speed");
  CheckNonNegative(bumps_per_km, "Vehicle.bumps_per_km");
  CheckOption(std::abs(bump_pitch_deg) <= 10.0, "Vehicle.bump_pitch_deg", "must lie in [-10, 10]");
  CheckPositive(bump_damping, "Vehicle.bump_damping");
  CheckPositive(bump_frequency_hz, "Vehicle.bump_frequency_hz");
  CheckOption(std::isfinite(pitch_per_acceleration_deg), "Vehicle.pitch_per_acceleration_deg",
              "must be a number");
  CheckNonNegative(start_position, "Vehicle.start_position");
}

void TrafficOptions::Check() const {
  CheckProbability(parked_fraction, "Traffic.parked_fraction");
  CheckPositive(lead_gap_min, "Traffic.lead_gap_min");
  CheckRange(lead_gap_min, lead_gap_max, "Traffic.lead_gap_min/max");
  CheckNonNegative(oncoming_per_km, "Traffic.oncoming_per_km");
  CheckNonNegative(same_direction_per_km, "Traffic.same_direction_per_km");
  CheckNonNegative(overtaking_per_km, "Traffic.overtaking_per_km");
  CheckPositive(car_speed_min, "Traffic.car_speed_min");
  CheckRange(car_speed_min, car_speed_max, "Traffic.car_speed_min/max");
  CheckNonNegative(pedestrians_per_100m, "Traffic.pedestrians_per_100m");
}

void SceneryOptions::Check() const {
  CheckProbability(building_fraction, "Scenery.building_fraction");
  CheckNonNegative(building_setback_min, "Scenery.building_setback_min");
  CheckRange(building_setback_min, building_setback_max, "Scenery.building_setback_min/max");
  CheckPositive(building_height_min, "Scenery.building_height_min");
  CheckRange(building_height_min, building_height_max, "Scenery.building_height_min/max");
  CheckPositive(building_width_min, "Scenery.building_width_min");
  CheckRange(building_width_min, building_width_max, "Scenery.building_width_min/max");
  CheckNonNegative(tree_spacing, "Scenery.tree_spacing");
  CheckProbability(tree_probability, "Scenery.tree_probability");
  CheckNonNegative(pole_spacing, "Scenery.pole_spacing");
  CheckProbability(wall_probability, "Scenery.wall_probability");
  CheckProbability(vegetation_probability, "Scenery.vegetation_probability");
  CheckNonNegative(backdrop_trees, "Scenery.backdrop_trees");
}

void LabelErrorOptions::Check() const {
  CheckOption(dynamic_erosion_px >= 0 && dynamic_erosion_px <= 50, "Labels.dynamic_erosion_px",
              "must lie in [0, 50]");
  CheckOption(dynamic_lag_frames >= 0 && dynamic_lag_frames <= 30, "Labels.dynamic_lag_frames",
              "must lie in [0, 30]");
  CheckOption(dynamic_dropout >= 0.0 && dynamic_dropout <= 1.0, "Labels.dynamic_dropout",
              "must lie in [0, 1]");
}

void TextureOptions::Check() const {
  CheckOption(std::isfinite(road_contrast) && road_contrast >= 0.0 && road_contrast <= 5.0,
              "Texture.road_contrast", "must lie in [0, 5]");
  CheckOption(std::isfinite(road_detail) && road_detail >= 0.0 && road_detail <= 5.0,
              "Texture.road_detail", "must lie in [0, 5]");
  CheckOption(std::isfinite(facade_contrast) && facade_contrast >= 0.0 && facade_contrast <= 5.0,
              "Texture.facade_contrast", "must lie in [0, 5]");
  CheckOption(std::isfinite(vegetation_contrast) && vegetation_contrast >= 0.0 &&
                  vegetation_contrast <= 5.0,
              "Texture.vegetation_contrast", "must lie in [0, 5]");
}

void ImageOptions::Check() const {
  camera.Check();
  CheckOption(camera.width <= 8192 && camera.height <= 8192, "Camera.width/height",
              "must be at most 8192");
  CheckPositive(frame_rate, "Image.frame_rate");
  CheckNonNegative(noise_sigma, "Image.noise_sigma");
  CheckOption(
      std::isfinite(exposure_variation) && exposure_variation >= 0.0 && exposure_variation < 1.0,
      "Image.exposure_variation", "must lie in [0, 1)");
  CheckPositive(exposure_period_s, "Image.exposure_period_s");
  CheckOption(sun_elevation_deg > 0.0 && sun_elevation_deg <= 90.0, "Image.sun_elevation_deg",
              "must lie in (0, 90]");
  CheckOption(std::isfinite(sun_azimuth_deg), "Image.sun_azimuth_deg", "must be a number");
  CheckOption(ambient >= 0.0 && ambient <= 1.0, "Image.ambient", "must lie in [0, 1]");
  CheckPositive(haze_distance, "Image.haze_distance");
  CheckOption(far_distance >= 20.0, "Image.far_distance", "must be at least 20 m");
  CheckOption(threads >= 1 && threads <= 64, "Image.threads", "must be 1..64");
}

void SceneOptions::Check() const {
  road.Check();
  vehicle.Check();
  traffic.Check();
  scenery.Check();
  texture.Check();
  labels.Check();
  image.Check();
}

const std::vector<std::string>& PresetNames() {
  static const std::vector<std::string> names = {"urban", "highway", "stop_and_go",
                                                 "hills", "bumpy",   "traffic_jam"};
  return names;
}

SceneOptions PresetSceneOptions(const std::string& name) {
  SceneOptions options;
  options.preset = name;
  if (name == "urban") {
    // The defaults: a KITTI-like town street with parked and moving cars.
    return options;
  }
  if (name == "highway") {
    // Fast, straight-ish, wide; little structure near the road, so few near points.
    RoadOptions& road = options.road;
    road.lane_width = 3.75;
    road.lanes_same = 2;
    road.lanes_opposite = 2;
    road.parking_width = 0.0;
    road.shoulder_width = 2.5;
    road.median_width = 3.0;
    road.kerb_height = 0.0;
    road.sidewalk_width = 0.0;
    road.verge_width = 4.0;
    road.ground_width = 50.0;
    road.paved_ground = false;
    road.crown_slope = 0.0;  // each carriageway drains to one side; not modelled
    road.straight_min = 300.0;
    road.straight_max = 700.0;
    road.radius_min = 700.0;
    road.radius_max = 2000.0;
    road.curve_angle_min_deg = 5.0;
    road.curve_angle_max_deg = 20.0;
    road.sharp_turn_probability = 0.0;
    road.grade_max = 0.03;
    road.bank_max_deg = 2.0;
    road.transition = 80.0;
    VehicleOptions& vehicle = options.vehicle;
    vehicle.initial_speed = 25.0;
    vehicle.speed_min = 24.0;
    vehicle.speed_max = 26.0;
    vehicle.stop_probability = 0.0;
    vehicle.pitch_amplitude_deg = 0.08;
    vehicle.suspension_speed = 20.0;
    TrafficOptions& traffic = options.traffic;
    traffic.parked_fraction = 0.0;
    traffic.lead_car = false;
    traffic.oncoming_per_km = 12.0;
    traffic.same_direction_per_km = 10.0;
    traffic.overtaking_per_km = 6.0;
    traffic.car_speed_min = 22.0;
    traffic.car_speed_max = 33.0;
    traffic.pedestrians_per_100m = 0.0;
    SceneryOptions& scenery = options.scenery;
    scenery.building_fraction = 0.0;
    scenery.tree_spacing = 0.0;
    scenery.pole_spacing = 50.0;
    scenery.wall_probability = 0.0;
    scenery.vegetation_probability = 0.0;
    scenery.backdrop_trees = 12.0;
    return options;
  }
  if (name == "stop_and_go") {
    // Town traffic that keeps stopping: long runs of stationary frames while other cars
    // and pedestrians move.
    VehicleOptions& vehicle = options.vehicle;
    vehicle.initial_speed = 0.0;
    vehicle.speed_min = 3.0;
    vehicle.speed_max = 7.0;
    vehicle.cruise_min_s = 3.0;
    vehicle.cruise_max_s = 7.0;
    vehicle.stop_probability = 0.8;
    vehicle.stop_min_s = 3.0;
    vehicle.stop_max_s = 8.0;
    options.traffic.lead_gap_min = 8.0;
    options.traffic.lead_gap_max = 14.0;
    options.traffic.pedestrians_per_100m = 5.0;
    return options;
  }
  if (name == "hills") {
    // Suburban road over hills: grade changes of up to 6 % and some bank, so the road
    // ahead is not the plane under the car.
    RoadOptions& road = options.road;
    road.parking_width = 0.0;
    road.sidewalk_width = 2.0;
    road.verge_width = 3.0;
    road.paved_ground = false;
    road.straight_min = 60.0;
    road.straight_max = 150.0;
    road.radius_min = 80.0;
    road.radius_max = 300.0;
    road.sharp_turn_probability = 0.05;
    road.grade_max = 0.06;
    road.grade_change_probability = 1.0;
    road.bank_max_deg = 2.5;
    road.transition = 40.0;
    options.vehicle.initial_speed = 11.0;
    options.vehicle.speed_min = 10.0;
    options.vehicle.speed_max = 15.0;
    options.vehicle.stop_probability = 0.0;
    options.traffic.parked_fraction = 0.0;
    options.traffic.lead_gap_min = 20.0;
    options.traffic.lead_gap_max = 35.0;
    options.traffic.pedestrians_per_100m = 0.5;
    options.scenery.building_fraction = 0.35;
    options.scenery.building_setback_min = 3.0;
    options.scenery.building_setback_max = 10.0;
    options.scenery.building_height_min = 5.0;
    options.scenery.building_height_max = 9.0;
    options.scenery.tree_probability = 0.7;
    options.scenery.backdrop_trees = 6.0;
    return options;
  }
  if (name == "bumpy") {
    // A rough street: strong pitch oscillation and bumps, so the camera's view of the
    // road plane changes every frame although its height does not.
    options.road.parking_width = 0.0;
    options.road.sharp_turn_probability = 0.1;
    options.vehicle.initial_speed = 8.0;
    options.vehicle.speed_min = 7.0;
    options.vehicle.speed_max = 11.0;
    options.vehicle.stop_probability = 0.0;
    options.vehicle.pitch_amplitude_deg = 0.8;
    options.vehicle.pitch_frequency_hz = 1.5;
    options.vehicle.roll_amplitude_deg = 0.4;
    options.vehicle.bumps_per_km = 30.0;
    options.vehicle.bump_pitch_deg = 1.5;
    options.traffic.parked_fraction = 0.0;
    options.scenery.building_fraction = 0.6;
    return options;
  }
  if (name == "traffic_jam") {
    // The paper's title scenario: dense town traffic at walking pace. The car creeps at up to
    // 2.5 m/s and slows smoothly to stops, a lead car 5-8 m ahead hides most of the lane,
    // slow cars fill the lanes beside it in both directions, pedestrians cross the view.
    options.road.lanes_same = 2;
    options.road.lanes_opposite = 1;
    VehicleOptions& vehicle = options.vehicle;
    vehicle.initial_speed = 1.5;
    vehicle.speed_min = 0.5;
    vehicle.speed_max = 2.5;
    vehicle.cruise_min_s = 2.0;
    vehicle.cruise_max_s = 6.0;
    vehicle.stop_probability = 0.6;
    vehicle.stop_min_s = 1.0;
    vehicle.stop_max_s = 4.0;
    vehicle.acceleration = 0.8;
    vehicle.deceleration = 0.8;
    TrafficOptions& traffic = options.traffic;
    traffic.parked_fraction = 0.8;
    traffic.lead_gap_min = 5.0;
    traffic.lead_gap_max = 8.0;
    traffic.oncoming_per_km = 120.0;
    traffic.same_direction_per_km = 150.0;
    traffic.overtaking_per_km = 0.0;
    traffic.car_speed_min = 1.0;
    traffic.car_speed_max = 4.0;
    traffic.pedestrians_per_100m = 8.0;
    return options;
  }
  std::string known;
  for (const std::string& preset : PresetNames()) known += (known.empty() ? "" : ", ") + preset;
  throw Error("unknown synthetic scene preset '" + name + "' (expected one of: " + known + ")");
}

}  // namespace roadscale::synth
