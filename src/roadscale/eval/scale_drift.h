#pragma once

#include <cstdint>
#include <vector>

#include "roadscale/io/trajectory_io.h"

namespace roadscale {

// A slowly drifting scale, as a monocular VO's trajectory has it: the factor of step k
// (from pose k-1 to pose k) is
//   s_k = initial_scale * exp(growth_per_step * k + w_k),  w_k = w_{k-1} + sigma * N(0, 1),
// with w_0 = 0. Used to destroy the scale of a ground truth so that `roadscale rescale` can be
// tested on a trajectory whose true metric scale is known.
struct ScaleDriftOptions {
  // s at the start: 0.3 external units per metre (any value: a monocular VO picks one).
  double initial_scale = 0.3;
  // Growth of log(s) per step: 0.002 makes the scale 1.5 times larger after 200 steps.
  double growth_per_step = 0.002;
  // Standard deviation of the random walk of log(s) per step: 0.002 (about 3 % after 200
  // steps), small beside the growth.
  double random_walk_sigma = 0.002;
  // Seed of the random walk (a platform-independent generator: same seed, same factors).
  uint64_t seed = 1;

  void Check() const;
};

// s_k for k = 0 .. num_poses - 1 (s_0, which no step uses, is initial_scale).
std::vector<double> ScaleDriftFactors(size_t num_poses, const ScaleDriftOptions& options);

// The trajectory with each step's translation (in the step's first camera frame) multiplied
// by its factor: the first pose, every rotation, every translation direction and the
// timestamps stay as they are. Throws Error on invalid options.
Trajectory DistortTrajectoryScale(const Trajectory& trajectory, const ScaleDriftOptions& options);

// Poses 0, every, 2 every, ... with their timestamps (a VO that outputs keyframes only).
// Throws Error unless every >= 1.
Trajectory KeepEveryNthPose(const Trajectory& trajectory, size_t every);

}  // namespace roadscale
