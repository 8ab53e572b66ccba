#pragma once

#include <optional>
#include <vector>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/mapping/local_window.h"
#include "roadscale/scale/road_plane.h"

#include <Eigen/Core>

namespace roadscale {

struct LandmarkTriangulatorOptions {
  // Smallest angle (degrees) between the two rays a landmark is triangulated from: below it
  // the depth is not determined (the scale stage's min_parallax_deg, for the same reason).
  // A track that fails waits for a later keyframe with a longer baseline.
  double min_parallax_deg = 0.5;
  // Largest reprojection error (pixels) in any keyframe that observes the landmark.
  double max_reprojection_error_px = 2.0;
  // A static point seen below the horizon cannot lie far beneath the road: its ray meets the
  // ground first. A track that caught the next post of a guard rail (posts about 2 m apart,
  // 2.5 m a frame at highway speed) or slid along a stripe moves less than the point it
  // started on, and its rays meet far below the road; straight ahead it still fits the
  // epipolar geometry, in a curve it pulls the rotation (on the rendered highways 91 % of the
  // tracks nearer than 30 m were such tracks, and the turns came out at 0.65-0.75 of their
  // angle). At every keyframe once the map is metric, a landmark more than this many camera
  // heights below the road plane under the newest keyframe is erased with its track (0: no
  // check); one height leaves room for ditches and for a road falling away ahead.
  double max_depth_below_ground = 1.0;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// One view of a point: the camera pose and the observed pixel.
struct PointView {
  Rigid3d cam_from_world;
  Eigen::Vector2d pixel;
};

// The point seen in `views` (at least two, in order of time): triangulated linearly from the
// earliest view and the later one whose ray makes the widest angle with it, then checked in
// every view (in front of the camera, reprojection error).
// Nothing when the angle or a view fails the options.
std::optional<Eigen::Vector3d> TriangulateMultiView(const std::vector<PointView>& views,
                                                    const PinholeCamera& camera,
                                                    const LandmarkTriangulatorOptions& options);

// Makes landmarks of the tracks the newest keyframe sees that are no landmarks yet and that
// earlier keyframes of the window saw too. Returns how many were made.
int TriangulateNewLandmarks(const PinholeCamera& camera, const LandmarkTriangulatorOptions& options,
                            LocalWindow* window);

// Erases the tracks whose landmarks lie more than options.max_depth_below_ground heights
// below `ground`, the road plane under the newest keyframe in its camera frame and the map's
// units (nothing when that option is 0), on rays that meet the ground within 20
// heights of the newest keyframe: their observations too, so that they are not triangulated
// again from the same views. Returns how many were erased.
int RemoveLandmarksBelowGround(const Plane& ground, const LandmarkTriangulatorOptions& options,
                               LocalWindow* window);

}  // namespace roadscale
