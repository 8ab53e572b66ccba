#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/synth/centre_line.h"

namespace roadscale::synth {

// Every knob of a synthetic scene. The defaults are the `urban` preset; the other presets
// start from them (see PresetSceneOptions). The YAML scene file sets any of them by the
// same names (docs/synthetic_scenes.md lists them).

// The road: lane layout, cross-section and how the centre line is generated.
struct RoadOptions {
  double lane_width = 3.5;      // metres
  int lanes_same = 1;           // lanes in the ego direction; the ego drives in the rightmost
  int lanes_opposite = 1;       // lanes of oncoming traffic
  double parking_width = 2.2;   // parking strip on each side of the carriageway (0: none)
  double shoulder_width = 0.0;  // asphalt shoulder on each side, outside the parking strip
  double median_width = 0.0;    // between the directions, with a concrete barrier when > 0
  double kerb_height = 0.15;    // sidewalks are this much above the road
  double sidewalk_width = 3.0;  // 0: no sidewalk (the verge starts at the road edge)
  double verge_width = 0.0;     // grass between the sidewalk and the ground beyond
  double ground_width = 30.0;   // ground beyond the verge (paved in towns, grass elsewhere)
  bool paved_ground = true;     // false: the ground beyond the verge is grass (terrain)
  double crown_slope = 0.02;    // cross fall of the carriageway to both edges (camber)

  // Generator of the centre line (used when `pieces` is empty).
  double straight_min = 40.0, straight_max = 120.0;  // metres
  double radius_min = 60.0, radius_max = 250.0;      // gentle curves, metres
  double curve_angle_min_deg = 10.0, curve_angle_max_deg = 45.0;
  double sharp_turn_probability = 0.3;  // a curve is a junction-like turn
  double sharp_radius_min = 15.0, sharp_radius_max = 25.0;
  double sharp_angle_min_deg = 60.0, sharp_angle_max_deg = 90.0;
  double grade_max = 0.02;  // |dz/du| of a piece, drawn uniformly
  double grade_change_probability = 0.5;
  double bank_max_deg = 1.0;
  double transition = 15.0;       // clothoid / vertical-curve length, metres
  std::vector<RoadPiece> pieces;  // an explicit road instead of the generator

  void Check() const;
};

// The ego vehicle: speed profile, camera mounting and suspension.
struct VehicleOptions {
  double h0 = 1.65;               // camera height above the road, metres (exact)
  double camera_pitch_deg = 0.0;  // mounting pitch, positive looks up
  double camera_roll_deg = 0.0;   // mounting roll, positive turns the image clockwise
  // How far ahead of the point that follows the lane (a car's rear axle) the camera sits,
  // metres. 0 (every preset): the camera moves along its optical axis, also in turns. On a
  // real car it does not: KITTI's cameras travel 8-10 degrees off their axis in 07's junction
  // turns (the ground truth's direction in the camera frame), as a camera about 1.3 m ahead
  // of the rear axle would.
  double camera_ahead = 0.0;
  double initial_speed = 5.0;                // m/s at frame 0
  double speed_min = 6.0, speed_max = 11.0;  // cruise speeds, m/s
  double cruise_min_s = 5.0, cruise_max_s = 15.0;
  double stop_probability = 0.15;  // after each cruise phase
  double stop_min_s = 2.0, stop_max_s = 5.0;
  double acceleration = 1.5, deceleration = 2.5;  // m/s^2
  // Suspension: sinusoids whose amplitude grows with speed up to `suspension_speed`, plus
  // damped bumps at random places, plus pitch from acceleration. None of them moves the
  // camera centre, so the camera stays exactly h0 above the road.
  double pitch_amplitude_deg = 0.1, pitch_frequency_hz = 1.4;
  double roll_amplitude_deg = 0.08, roll_frequency_hz = 0.9;
  double suspension_speed = 8.0;  // m/s at which the sinusoids reach full amplitude
  double bumps_per_km = 0.0;
  double bump_pitch_deg = 1.0;  // first swing of a bump
  double bump_damping = 3.0;    // 1/s
  double bump_frequency_hz = 1.6;
  double pitch_per_acceleration_deg = 0.12;  // nose dips this much per m/s^2 of braking
  double start_position = 40.0;              // metres of road behind the camera at frame 0

  void Check() const;
};

// Other road users.
struct TrafficOptions {
  double parked_fraction = 0.6;  // share of the parking strips occupied by cars
  bool lead_car = true;          // a car ahead in the ego lane that follows the ego's motion
  double lead_gap_min = 12.0, lead_gap_max = 30.0;   // metres ahead of the camera
  double oncoming_per_km = 40.0;                     // cars in the opposite lanes
  double same_direction_per_km = 10.0;               // cars in the other same-direction lanes
  double overtaking_per_km = 4.0;                    // cars that come from behind and pass the ego
  double car_speed_min = 6.0, car_speed_max = 13.0;  // m/s of free-moving cars
  double pedestrians_per_100m = 3.0;                 // on the sidewalks, walking or standing

  void Check() const;
};

// Static structure beside the road.
struct SceneryOptions {
  double building_fraction = 0.85;  // share of each side lined with buildings
  double building_setback_min = 0.0, building_setback_max = 4.0;  // behind the sidewalk
  double building_height_min = 7.0, building_height_max = 18.0;
  double building_width_min = 8.0, building_width_max = 25.0;
  double tree_spacing = 14.0;           // street trees along the sidewalk (0: none)
  double tree_probability = 0.5;        // chance of a tree at each spacing step
  double pole_spacing = 30.0;           // street lights (0: none)
  double wall_probability = 0.35;       // a low wall or fence in front of a gap between buildings
  double vegetation_probability = 0.5;  // trees and hedges in gaps between buildings
  double backdrop_trees = 0.0;          // tree rows per 100 m at the outer edge of the ground

  void Check() const;
};

// Surface appearance; 1 is KITTI-like.
struct TextureOptions {
  double road_contrast = 1.0;    // asphalt grain and patches
  double road_detail = 1.0;      // density of cracks, seams and repairs on the road
  double facade_contrast = 1.0;  // windows, bricks, plaster
  double vegetation_contrast = 1.0;
  bool shadows = true;  // cast shadows of cars and trees on the road

  void Check() const;
};

// The camera image.
struct ImageOptions {
  PinholeCamera camera = KittiOdometryCamera();
  double frame_rate = 10.0;         // Hz
  double noise_sigma = 1.0;         // grey levels of Gaussian image noise
  double exposure_variation = 0.0;  // relative amplitude of a slow gain change
  double exposure_period_s = 15.0;
  double sun_elevation_deg = 40.0, sun_azimuth_deg = 60.0;
  double ambient = 0.5;          // share of light that does not depend on orientation
  double haze_distance = 350.0;  // metres over which contrast falls to 1/e
  double far_distance = 260.0;   // nothing is drawn beyond this depth
  int threads = 2;               // rendering threads; the output does not depend on it

  void Check() const;
};

// Errors of a segmentation network's labels on real frames, for semantic_network/ beside the
// exact semantic/ (all 0: not written). Each is what the shared ESPNetv2 does on KITTI's real
// frames: outlines of cars a few pixels small at their edges, late on traffic that moves
// across the image, and a car missing in one frame and back in the next.
struct LabelErrorOptions {
  int dynamic_erosion_px = 0;    // moving objects' outlines shrunk by this much
  int dynamic_lag_frames = 0;    // moving objects labelled where they were this many frames ago
  double dynamic_dropout = 0.0;  // chance that an object is missed (reads as road) in a frame

  bool Any() const {
    return dynamic_erosion_px > 0 || dynamic_lag_frames > 0 || dynamic_dropout > 0.0;
  }
  void Check() const;
};

struct SceneOptions {
  std::string preset = "urban";
  uint64_t seed = 1;
  RoadOptions road;
  VehicleOptions vehicle;
  TrafficOptions traffic;
  SceneryOptions scenery;
  TextureOptions texture;
  ImageOptions image;
  LabelErrorOptions labels;

  void Check() const;
};

// urban, highway, stop_and_go, hills, bumpy, traffic_jam; throws Error for any other name.
SceneOptions PresetSceneOptions(const std::string& name);
const std::vector<std::string>& PresetNames();

}  // namespace roadscale::synth
