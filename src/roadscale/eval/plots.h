#pragma once

#include <string>
#include <vector>

#include "roadscale/eval/kitti_odometry_metric.h"
#include "roadscale/geometry/rigid3.h"

namespace roadscale {

// Writes the evaluation's figures with Cairo, each as PNG and SVG, into `directory`
// (created when missing):
//   trajectory_top_view   ground truth and estimate seen from above: the x-z plane of the
//                         world (KITTI: x right, z forward), metres, equal axes, start
//                         marked, with a legend;
//   t_err_vs_length       the devkit's plot: translation error [%] against segment length;
//   r_err_vs_length       the devkit's plot: rotation error [deg/m] against segment length.
// The devkit draws a length only when at least 3 of its segments fit; these plots draw
// every length that fits at all and say so when none does. Returns the written paths;
// throws Error naming the file when one cannot be written.
std::vector<std::string> WriteEvaluationPlots(const std::string& directory,
                                              const std::vector<Rigid3d>& gt_world_from_cam,
                                              const std::vector<Rigid3d>& est_world_from_cam,
                                              const KittiOdometryResult& kitti);

}  // namespace roadscale
