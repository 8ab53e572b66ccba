#include "roadscale/eval/scale_drift.h"

#include <cmath>

#include "roadscale/util/error.h"
#include "roadscale/util/random.h"

namespace roadscale {

void ScaleDriftOptions::Check() const {
  CheckOption(std::isfinite(initial_scale) && initial_scale > 0.0, "scale_drift.initial_scale",
              "must be a positive number");
  CheckOption(std::isfinite(growth_per_step), "scale_drift.growth_per_step",
              "must be a finite number");
  CheckOption(std::isfinite(random_walk_sigma) && random_walk_sigma >= 0.0,
              "scale_drift.random_walk_sigma", "must be a non-negative number");
}

std::vector<double> ScaleDriftFactors(size_t num_poses, const ScaleDriftOptions& options) {
  options.Check();
  Rng rng(options.seed);
  std::vector<double> factors;
  factors.reserve(num_poses);
  double walk = 0.0;
  for (size_t k = 0; k < num_poses; ++k) {
    if (k > 0) walk += options.random_walk_sigma * rng.Normal();
    factors.push_back(options.initial_scale *
                      std::exp(options.growth_per_step * static_cast<double>(k) + walk));
  }
  return factors;
}

Trajectory DistortTrajectoryScale(const Trajectory& trajectory, const ScaleDriftOptions& options) {
  const std::vector<double> factors = ScaleDriftFactors(trajectory.size(), options);
  Trajectory distorted;
  distorted.timestamps = trajectory.timestamps;
  distorted.world_from_cam.reserve(trajectory.size());
  for (size_t k = 0; k < trajectory.size(); ++k) {
    if (k == 0) {
      distorted.world_from_cam.push_back(trajectory.world_from_cam[0]);
      continue;
    }
    Rigid3d prev_from_cur =
        trajectory.world_from_cam[k - 1].inverse() * trajectory.world_from_cam[k];
    prev_from_cur.translation() *= factors[k];
    distorted.world_from_cam.push_back(distorted.world_from_cam.back() * prev_from_cur);
  }
  return distorted;
}

Trajectory KeepEveryNthPose(const Trajectory& trajectory, size_t every) {
  if (every < 1) throw Error("keep every n-th pose: n must be at least 1");
  Trajectory kept;
  for (size_t k = 0; k < trajectory.size(); k += every) {
    kept.world_from_cam.push_back(trajectory.world_from_cam[k]);
    if (trajectory.HasTimestamps()) kept.timestamps.push_back(trajectory.timestamps[k]);
  }
  return kept;
}

}  // namespace roadscale
