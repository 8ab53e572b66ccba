#pragma once

#include <optional>
#include <vector>

#include "roadscale/geometry/rigid3.h"

namespace roadscale {

// The KITTI odometry benchmark's metric (devkit `evaluate_odometry.cpp`), written from its
// definition:
//  - dist[i] = path length of the ground truth up to frame i (sum of distances between
//    consecutive positions);
//  - a segment starts at every `step_frames`-th frame a = 0, 10, 20, ... and, for each
//    length L, ends at the first frame b >= a with dist[b] > dist[a] + L; starts without
//    such a frame are skipped;
//  - error pose E = inv(inv(Est_a) Est_b) inv(Gt_a) Gt_b; t_err = |translation(E)| / L and
//    r_err = angle(E) / L with angle = acos(max(min(0.5 (trace(R) - 1), 1), -1));
//  - the result is the mean over all segments of all lengths (pooled), and per length.
// Precision as in the devkit: poses, their products and their (general, Gauss-Jordan with
// full pivoting) inverses in double; the path distances (double differences rounded to
// float, float sums), the error pose's translation and diagonal, the per-segment errors and
// their means (float sums in the devkit's order: start frame outer, length inner) in single
// precision. Float distances decide the segment end frames, and so the numbers the benchmark
// prints; a double implementation differs by up to about 5e-4 relative. With the same split
// of precision the result matches the devkit's to about 1e-7 relative; float matrix
// arithmetic would move r_err by ~1e-4 (the float acos of a cosine near 1 is coarse for the
// small angles of good estimates and magnifies every rounding before it).
struct KittiMetricOptions {
  // Segment lengths in metres (the devkit's 100, 200, ..., 800).
  std::vector<float> lengths_m = {100, 200, 300, 400, 500, 600, 700, 800};
  // A segment starts every this many frames (the devkit's 10).
  int step_frames = 10;

  void Check() const;
};

struct KittiSegmentError {
  int first_frame = 0;
  int last_frame = 0;
  float length_m = 0;
  float t_err = 0;  // translation error / length (ratio; x100 for %)
  float r_err = 0;  // rotation error / length (rad/m)
};

struct KittiLengthResult {
  float length_m = 0;
  int n_segments = 0;
  // Means over this length's segments; empty when no segment of this length fits.
  std::optional<float> t_err;
  std::optional<float> r_err;
};

struct KittiOdometryResult {
  std::vector<KittiSegmentError> segments;    // in the devkit's order
  std::vector<KittiLengthResult> per_length;  // one per option length, in the options' order
  // Pooled means over `segments`; empty when no segment fits.
  std::optional<float> t_err;
  std::optional<float> r_err;
  // The ground truth's path length (float, as the devkit sums it).
  float gt_path_length_m = 0;

  int n_segments() const { return static_cast<int>(segments.size()); }
};

// Needs one estimated pose per ground-truth pose (pair them first, by index or by time);
// throws Error otherwise, and when the trajectories are empty.
KittiOdometryResult EvaluateKittiOdometry(const std::vector<Rigid3d>& gt_world_from_cam,
                                          const std::vector<Rigid3d>& est_world_from_cam,
                                          const KittiMetricOptions& options = {});

// The devkit's rotation angle of a (float) rotation block, in radians.
float KittiRotationError(const Eigen::Matrix3f& rotation);

// dist[i] as the devkit sums it.
std::vector<float> KittiPathDistances(const std::vector<Rigid3d>& world_from_cam);

}  // namespace roadscale
