#pragma once

#include <optional>
#include <vector>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/scale/road_plane.h"

#include <Eigen/Core>

namespace roadscale {

// Beyond the paper: the road plane refitted where the measurements are, in pixels.
//
// A point on the plane n.X = h seen at pixel x_prev (ray r = K^-1 x_prev, r.z = 1) lands in the
// current image at pi(K (R r + t (w.r))) with w = n / h: the plane-induced homography. The
// refit minimises the distances between these predictions and the tracked current pixels of
// RANSAC's inliers (robust Huber weights), which is the maximum-likelihood plane under
// pixel noise: triangulated points carry their error along the viewing rays, growing with the
// square of the depth, which tilts a least-squares plane in 3-D (the inverse-depth refit measured
// in docs/benchmark-history.md).
//
// With `refine_rotation` the rotation is refined with the plane (three more unknowns). For a
// car driving forward the essential matrix hardly tells a small pitch rotation from a small
// change of the translation's direction, and 0.035 deg of pitch moves a road point 0.4 px:
// about 4 % of its depth at 10 m, the same for every road point of the frame, so it does not
// average out. The road separates the two: a rotation moves every pixel alike, the plane's
// translation flow grows with the square of the distance below the horizon.
//
// With `tangent_to_travel` the normal stays perpendicular to the direction of travel
// d = -R^T t (both camera centres h above a planar road, Alg. 2's premise): w keeps two
// unknowns. Without it, the plane's pitch and a pitch rotation are nearly interchangeable
// for points seen in a narrow band below the horizon.
struct RoadHomographyRefitOptions {
  // Off by default: with the frontend's refined motion it did not help (KITTI 00 t_err 1.29 %
  // against 1.31 %, rendered drives 1.12 % against 0.78 %): the rotation, fitted on every
  // track, is already better than what the road's tracks alone can tell.
  bool refine_rotation = false;
  bool tangent_to_travel = true;
  // Without tangent_to_travel, > 0 pulls the normal towards perpendicular to the travel
  // instead of holding it there: a tilt of 1 degree costs as much as one track this many
  // pixels off (3: a tilt of 0.1 deg weighs as a track 0.3 px off, KLT's accuracy). For roads
  // whose grade changes ahead (hills), where the car's own plane is not the road's ahead.
  // 0: no pull (a free normal).
  double travel_prior_px_per_deg = 0.0;
  // Huber loss scale in pixels: KLT tracks are good to a few tenths of a pixel.
  double loss_scale_px = 1.0;
  int max_iterations = 10;

  void Check() const;
};

struct RoadHomographyRefit {
  Plane plane;                                             // in the previous camera's frame
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // refined (or the given) R
  double rotation_change_rad = 0.0;                        // angle between the two
  double rms_px = 0.0;                                     // transfer error after the refit
  int iterations = 0;
};

// Refits `initial` (and the rotation of `cur_from_prev`; its translation is used as a unit
// direction) on the tracks prev_pixels[i] -> cur_pixels[i] for i in `indices`. nullopt when
// fewer than 6 tracks are given, the normal equations are singular, or the result has the
// camera on or below the plane.
std::optional<RoadHomographyRefit> RefitRoadHomography(
    const std::vector<Eigen::Vector2d>& prev_pixels, const std::vector<Eigen::Vector2d>& cur_pixels,
    const std::vector<int>& indices, const Rigid3d& cur_from_prev, const PinholeCamera& camera,
    const Plane& initial, const RoadHomographyRefitOptions& options);

// The current pixel of the road point seen at `prev_pixel`, under the plane n.X = h
// (w = n / h) and the motion (R, t): pi(K (R r + t (w.r))). nullopt behind the camera.
std::optional<Eigen::Vector2d> TransferThroughRoadPlane(const Eigen::Vector2d& prev_pixel,
                                                        const Eigen::Matrix3d& rotation,
                                                        const Eigen::Vector3d& translation,
                                                        const Eigen::Vector3d& w,
                                                        const PinholeCamera& camera);

}  // namespace roadscale
