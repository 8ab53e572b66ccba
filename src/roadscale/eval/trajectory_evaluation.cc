#include "roadscale/eval/trajectory_evaluation.h"

namespace roadscale {

TrajectoryEvaluation EvaluateTrajectory(const std::vector<Rigid3d>& gt_world_from_cam,
                                        const std::vector<Rigid3d>& est_world_from_cam,
                                        const KittiMetricOptions& kitti_options) {
  TrajectoryEvaluation evaluation;
  evaluation.errors = ComputeTrajectoryErrors(gt_world_from_cam, est_world_from_cam);
  evaluation.kitti = EvaluateKittiOdometry(gt_world_from_cam, est_world_from_cam, kitti_options);
  evaluation.frames = gt_world_from_cam.size();
  return evaluation;
}

}  // namespace roadscale
