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

// The same figures (and two per-frame ones) as SVG documents in memory, for pages that
// inline them (html_report.h). Each throws Error when Cairo cannot draw it.

// The top view above; `gt_world_from_cam` may be empty (no ground truth: the estimate alone,
// its start marked). The two trajectories need not have the same number of poses.
// `keyframes`: indices into the estimate drawn as small circles on it.
std::string RenderTopViewSvg(const std::vector<Rigid3d>& gt_world_from_cam,
                             const std::vector<Rigid3d>& est_world_from_cam, int width = 800,
                             int height = 800, const std::vector<size_t>& keyframes = {});

enum class KittiErrorKind { kTranslation, kRotation };

// t_err_vs_length or r_err_vs_length above.
std::string RenderKittiErrorSvg(const KittiOdometryResult& kitti, KittiErrorKind kind,
                                int width = 800, int height = 500);

// One line of a per-frame figure: values[i] belongs to frame i; NaN (or any non-finite
// value) leaves a gap, and a value with no neighbour is drawn as a dot.
struct FrameLine {
  std::string label;
  std::vector<double> values;
};

struct FrameLinePlot {
  std::string title;
  std::string y_title;
  std::vector<FrameLine> lines;  // coloured in order from a fixed palette, legend at the right
  // Counts and times: the y axis starts at 0 (when no value is negative).
  bool y_from_zero = false;
};

// Lines against the frame index; says "no values" when no line has one.
std::string RenderFrameLinesSvg(const FrameLinePlot& plot, int width = 1100, int height = 380);

// A strip with one coloured cell per frame (frame i's status), and a legend of the statuses
// in order of first appearance with their frame counts.
std::string RenderFrameStatusSvg(const std::vector<std::string>& status, int width = 1100,
                                 int height = 150);

}  // namespace roadscale
