#pragma once

#include <vector>

#include "roadscale/eval/kitti_odometry_metric.h"
#include "roadscale/eval/trajectory_errors.h"
#include "roadscale/geometry/rigid3.h"

namespace roadscale {

// Everything `roadscale eval` reports about one estimated trajectory.
struct TrajectoryEvaluation {
  size_t frames = 0;  // number of evaluated pose pairs
  KittiOdometryResult kitti;
  TrajectoryErrors errors;
};

// Evaluates paired poses (see PairPoses): the KITTI devkit metric and the trajectory errors.
// Throws Error unless both have the same number of poses, at least 2.
TrajectoryEvaluation EvaluateTrajectory(const std::vector<Rigid3d>& gt_world_from_cam,
                                        const std::vector<Rigid3d>& est_world_from_cam,
                                        const KittiMetricOptions& kitti_options = {});

}  // namespace roadscale
