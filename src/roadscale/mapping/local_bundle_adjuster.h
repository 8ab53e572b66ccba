#pragma once

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/mapping/local_window.h"

namespace roadscale {

struct LocalBundleAdjusterOptions {
  // Levenberg-Marquardt iterations per keyframe. The window starts near its optimum (one new
  // keyframe, localised against the map), so a few do; a bound keeps the time per keyframe
  // bounded too.
  int max_iterations = 10;
  // Huber scale of the reprojection errors (pixels): KLT tracks are accurate to a few tenths.
  double reprojection_loss_px = 1.0;
  // After the solve, observations whose error exceeds this (pixels) are removed, and
  // landmarks left with fewer than two observations.
  double max_reprojection_error_px = 3.0;
  // Road term (camera_height_residual.h): sigma of a road point's height about the plane
  // (metres) and its Huber scale in sigmas.
  double camera_height_sigma_m = 0.05;
  double camera_height_loss = 1.0;
  // With at least this many road landmarks in the window, or any road pair in the
  // adjustment, the road decides the window's scale (only the oldest keyframe is fixed);
  // otherwise the two oldest keyframes are fixed and the scale is the one the map carries. 12 is
  // what the paper asks of one road plane (ransac_min_points). 24 left the rendered traffic jam
  // without any scale (length 5.9 times the truth) and drifted on the highway; 12 gives 0.980
  // and 3.1 % there and ties elsewhere (docs/benchmark-history.md, "Keyframe back end").
  int min_road_landmarks = 12;
  // After a solve that set the scale, road marks whose height is off by more than this many
  // sigmas are dropped (a kerb or a car's bottom that the selection let through), and road
  // pairs are taken out of the adjustment unless the window's pairs agree on them (the map
  // drifted, not they): a pair measured on a road mask is dropped, one measured on the region
  // ahead stays as a reading that votes and comes back (ReviewRoadPairs).
  double road_outlier_sigmas = 4.0;
  // Pair term (road_pair_residual.h): sigma of a keyframe pair's camera height measured by
  // the road alignment (metres). The alignment's |t| / h is within 0.5-0.9 % (median) of the
  // truth on rendered drives (bench/road_alignment_accuracy.cc): 0.02 m is 1.2 % of 1.65 m.
  double road_pair_sigma_m = 0.02;

  // Throws Error naming the first invalid option.
  void Check() const;
};

struct BundleAdjustmentReport {
  bool ran = false;
  bool scale_from_road = false;  // the road set the scale (see min_road_landmarks)
  int iterations = 0;
  double initial_cost = 0.0;  // Ceres' cost (half the sum of squared robust residuals)
  double final_cost = 0.0;
  int num_keyframes = 0;
  int num_landmarks = 0;
  int num_road_landmarks = 0;
  int num_road_pairs = 0;  // keyframe pairs with a road alignment in the window
  int removed_observations = 0;
  int removed_road_marks = 0;  // road landmarks unmarked and road pairs taken out
  double milliseconds = 0.0;
};

// Bundle adjustment of the window: keyframe poses and landmarks by their reprojection errors
// (Huber), the road landmarks' heights (the camera-height term) and the keyframe pairs' road
// alignments (the pair term). The oldest keyframe is fixed (the gauge: position and
// orientation), and with too few road landmarks and no pair term the second oldest too (the
// scale); so is the first keyframe of each later part that no landmark ties to the keyframes
// before it (tracking lost in between). Removes the observations and road marks it finds
// wrong.
// `camera_height` is h0 in metres.
BundleAdjustmentReport AdjustLocalWindow(const PinholeCamera& camera, double camera_height,
                                         const LocalBundleAdjusterOptions& options,
                                         LocalWindow* window);

}  // namespace roadscale
