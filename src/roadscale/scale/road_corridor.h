#pragma once

#include <vector>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"

#include <Eigen/Core>

namespace roadscale {

// Beyond the paper: keep the road points in the corridor the car is about to drive over.
// Points far to the side are raised sidewalks, lawns, medians or cambered road (3-5 cm above
// the lane beyond 3 m); far points have little parallax, and their depth errors tilt the
// fitted plane. The test uses the pixel alone, never the noisy triangulated depth: the pixel's
// viewing ray is intersected with the expected road plane (the motion's road normal n_r at
// the camera height h0, in metres), so it cannot favour points triangulated too near or too
// far.
struct RoadCorridorOptions {
  bool enabled = false;  // off: the paper
  // Largest lateral distance from the vehicle's path, in metres. A lane is about 3.5 m wide
  // and camber lifts the road noticeably beyond 3 m: 3 m keeps the car's lane and the nearer
  // half of the next, and drops kerbs and sidewalks of a two-lane street.
  double half_width_m = 3.0;
  // Largest distance ahead, in metres, along the path. Heights are consistent to about 30 m
  // and good inliers come from within about 16 m on KITTI; 20 m sits between.
  double max_distance_m = 20.0;
  // Bend the corridor along the circle that the motion's yaw implies (needs the metric step,
  // taken from the last scale; straight until there is one).
  bool follow_turn = true;

  void Check() const;
};

// Where a pixel's ray meets the expected road, in the road frame of the travel direction:
// `ahead` along the direction of travel, `lateral` to the right of the travel line (both in
// metres). `valid` is false when the ray does not meet the road ahead of the camera.
struct RoadFootprint {
  bool valid = false;
  double ahead = 0.0;
  double lateral = 0.0;
};

RoadFootprint FootprintOnRoad(const Eigen::Vector2d& pixel, const PinholeCamera& camera,
                              const Eigen::Vector3d& road_normal,
                              const Eigen::Vector3d& travel_direction, double camera_height_m);

// The yaw of the motion about the road normal, in radians, positive for a right turn (x
// right, y down: a rotation about +n_r turns z towards x).
double YawAboutRoadNormal(const Rigid3d& cur_from_prev, const Eigen::Vector3d& road_normal);

// Indices of the pixels whose footprint lies in the corridor: ahead in (0, max_distance_m]
// and within half_width_m of the path. The path is the travel line, or with follow_turn and
// step_m > 0 the arc of curvature yaw / step_m through both camera centres, whose offset
// from the travel line (the chord) is k s^2 / 2 - (yaw / 2) s at distance s.
std::vector<int> SelectRoadCorridor(const std::vector<Eigen::Vector2d>& pixels,
                                    const PinholeCamera& camera, const Rigid3d& cur_from_prev,
                                    const Eigen::Vector3d& road_normal, double camera_height_m,
                                    double step_m, const RoadCorridorOptions& options);

}  // namespace roadscale
