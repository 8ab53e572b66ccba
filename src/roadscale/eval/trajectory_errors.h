#pragma once

#include <optional>
#include <vector>

#include "roadscale/geometry/rigid3.h"

namespace roadscale {

// Errors of an estimated trajectory against the ground truth, pose i against pose i
// (pair them first). Computed in double precision.
struct TrajectoryErrors {
  // Absolute trajectory error: RMSE of the camera positions, in metres.
  // none: positions compared as given (both trajectories share their world frame, as they
  //       do when both start at the identity, like KITTI's);
  // se3:  after the rigid alignment of the estimate onto the ground truth (Umeyama);
  // sim3: after the similarity alignment; sim3_scale is its scale (multiplying the
  //       estimate's positions: 0.8 for an estimate 1.25 times too large). Both are empty
  //       when the estimated positions all coincide (no scale can be fitted).
  double ate_none_m = 0;
  double ate_se3_m = 0;
  std::optional<double> ate_sim3_m;
  std::optional<double> sim3_scale;

  // Relative pose error between consecutive frames, E_i = inv(inv(Gt_i) Gt_i+1)
  // inv(Est_i) Est_i+1: RMSE of |translation(E_i)| in metres and of angle(E_i) in degrees.
  double rpe_trans_rmse_m = 0;
  double rpe_rot_rmse_deg = 0;

  // Path lengths (sum of distances between consecutive positions), their ratio est / gt
  // (empty when the ground truth does not move), and the distance between the last
  // positions, in metres and in % of the ground-truth path (empty when it does not move).
  double gt_path_length_m = 0;
  double est_path_length_m = 0;
  std::optional<double> length_ratio;
  double final_drift_m = 0;
  std::optional<double> final_drift_pct;
};

// Throws Error unless both trajectories have the same number of poses, at least 2.
TrajectoryErrors ComputeTrajectoryErrors(const std::vector<Rigid3d>& gt_world_from_cam,
                                         const std::vector<Rigid3d>& est_world_from_cam);

// Sum of distances between consecutive camera positions, in metres.
double PathLength(const std::vector<Rigid3d>& world_from_cam);

}  // namespace roadscale
