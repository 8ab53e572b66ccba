// `roadscale eval`: evaluates an estimated trajectory against ground truth with the KITTI
// benchmark's metric (as its devkit computes it), ATE, RPE, path-length ratio and drift.
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "roadscale/eval/metrics_json.h"
#include "roadscale/eval/plots.h"
#include "roadscale/eval/pose_pairing.h"
#include "roadscale/eval/report_table.h"
#include "roadscale/eval/trajectory_evaluation.h"
#include "roadscale/io/kitti_calib.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/util/error.h"

#include "commands.h"

namespace roadscale::cli {
namespace {

struct EvalArguments {
  std::string gt;
  std::string est;
  std::string format = "kitti";
  std::string gt_format;
  std::string times;
  double max_time_diff = TimeAssociationOptions().max_difference_s;
  bool json = false;
  std::string plot_dir;
};

Trajectory ReadNonEmpty(const std::string& path, TrajectoryFormat format) {
  Trajectory trajectory = ReadTrajectory(path, format);
  if (trajectory.size() == 0) ThrowFileError(path, "no poses in the file");
  return trajectory;
}

void RunEval(const EvalArguments& arguments) {
  const TrajectoryFormat est_format = ParseTrajectoryFormat(arguments.format);
  const TrajectoryFormat gt_format =
      arguments.gt_format.empty() ? est_format : ParseTrajectoryFormat(arguments.gt_format);
  TimeAssociationOptions association;
  association.max_difference_s = arguments.max_time_diff;
  association.Check();

  Trajectory gt = ReadNonEmpty(arguments.gt, gt_format);
  const Trajectory est = ReadNonEmpty(arguments.est, est_format);
  if (!arguments.times.empty()) {
    if (gt.HasTimestamps()) {
      throw Error("--times gives timestamps to a KITTI ground truth, but " + arguments.gt +
                  " is a TUM file with its own");
    }
    gt.timestamps = ReadKittiTimes(arguments.times);
    if (gt.timestamps.size() != gt.size()) {
      ThrowFileError(arguments.times, "has " + std::to_string(gt.timestamps.size()) +
                                          " timestamps but " + arguments.gt + " has " +
                                          std::to_string(gt.size()) + " poses");
    }
  }

  const PosePairs pairs = PairPoses(gt, est, arguments.gt, arguments.est, association);
  const TrajectoryEvaluation evaluation =
      EvaluateTrajectory(pairs.gt_world_from_cam, pairs.est_world_from_cam);

  std::ostringstream pairing;
  if (pairs.by_time) {
    pairing << "by time: " << pairs.size() << " pairs with timestamps within "
            << association.max_difference_s << " s";
  } else {
    pairing << "pose i with pose i";
  }
  if (arguments.json) {
    std::cout << FormatMetricsJson(evaluation);
  } else {
    std::cout << "Ground truth: " << arguments.gt << " (" << gt.size() << " poses)\n"
              << "Estimate:     " << arguments.est << " (" << est.size() << " poses)\n"
              << "Paired:       " << pairing.str() << "\n"
              << FormatEvaluationTable(evaluation);
  }
  if (!arguments.plot_dir.empty()) {
    const std::vector<std::string> written = WriteEvaluationPlots(
        arguments.plot_dir, pairs.gt_world_from_cam, pairs.est_world_from_cam, evaluation.kitti);
    // Keep stdout pure JSON with --json.
    std::ostream& out = arguments.json ? std::cerr : std::cout;
    out << "Plots:";
    for (const std::string& path : written) out << ' ' << path;
    out << '\n';
  }
}

}  // namespace

void RegisterEvalCommand(CLI::App& app) {
  auto arguments = std::make_shared<EvalArguments>();
  CLI::App* command = app.add_subcommand(
      "eval",
      "Evaluate an estimated trajectory against ground truth: the KITTI odometry benchmark's "
      "t_err/r_err (computed as its devkit does), ATE (none/se3/sim3), "
      "per-frame RPE, path-length ratio and final drift. Pose i is compared with pose i "
      "(same count needed) unless both trajectories have timestamps (a TUM file, or KITTI "
      "poses with --times): then they are associated by time, as evo does.");
  command->add_option("--gt", arguments->gt, "Ground-truth trajectory file")->required();
  command->add_option("--est", arguments->est, "Estimated trajectory file")->required();
  command
      ->add_option("--format", arguments->format,
                   "Format of the estimate, and of the ground truth unless --gt-format: kitti "
                   "(12 numbers a row, 3x4 world_from_cam) or tum (timestamp tx ty tz qx qy qz "
                   "qw)")
      ->capture_default_str();
  command->add_option("--gt-format", arguments->gt_format,
                      "Format of the ground truth: kitti or tum (default: --format)");
  command->add_option("--times", arguments->times,
                      "KITTI times.txt giving the ground truth's timestamps, so that a TUM "
                      "estimate is associated with it by time (default: none)");
  command
      ->add_option("--max-time-diff", arguments->max_time_diff,
                   "Largest timestamp difference in seconds when associating by time (as evo's "
                   "--t_max_diff)")
      ->capture_default_str();
  command->add_flag("--json", arguments->json,
                    "Print the metrics as JSON instead of the table (default: off)");
  command->add_option("--plot", arguments->plot_dir,
                      "Write the top view and the devkit's error-vs-length plots (PNG and SVG) "
                      "to this folder (default: no plots)");
  command->callback([arguments] { RunEval(*arguments); });
}

}  // namespace roadscale::cli
