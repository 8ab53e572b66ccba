#pragma once

#include <vector>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"

#include <Eigen/Core>

namespace roadscale {

struct TriangulationOptions {
  // Smallest angle between the two viewing rays at the point. A point's relative depth error
  // is about (pixel noise angle) / (parallax), and its depth is biased high by about the
  // square of that ratio (depth is the inverse of a noisy parallax): at 0.5 deg with 0.3 px of
  // noise in each of KITTI's images that is 7 % and 0.5 % for the points at the limit, less
  // for the nearer ones. Road points in front of a car that drives 1 m a frame reach 0.5 deg
  // at about 13 m, those to the side farther away; at 0.5 m a frame, at about 9 m.
  double min_parallax_deg = 0.5;
  // Largest reprojection error, in either image, of the triangulated point. The tracks are
  // already the motion's inliers; this only drops gross mismatches.
  double max_reprojection_error_px = 2.0;

  void Check() const;
};

// Points triangulated from matched pixels with a unit baseline, in the previous camera's
// frame, and why the others were rejected.
struct TriangulatedPoints {
  std::vector<Eigen::Vector3d> points;  // in the previous camera's frame
  std::vector<int> track_indices;       // index of each point's pixel pair in the input
  int num_behind_camera = 0;
  int num_small_parallax = 0;
  int num_large_reprojection_error = 0;
};

// Linear (DLT) triangulation in normalised image coordinates of each pair
// (prev_pixels[i], cur_pixels[i]) seen by `camera` from the previous camera [I | 0] and the
// current one cur_from_prev = [R | t]. The translation is scaled to unit length first, so the
// result is in units of the baseline. Throws Error when the two lists differ in size.
TriangulatedPoints TriangulateUnitBaseline(const std::vector<Eigen::Vector2d>& prev_pixels,
                                           const std::vector<Eigen::Vector2d>& cur_pixels,
                                           const Rigid3d& cur_from_prev,
                                           const PinholeCamera& camera,
                                           const TriangulationOptions& options);

}  // namespace roadscale
