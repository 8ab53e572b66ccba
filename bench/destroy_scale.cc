// Destroys the scale of a ground-truth trajectory the way a monocular VO has it (a seeded,
// slowly drifting factor, eval/scale_drift.h), optionally keeping keyframes only, so that
// `roadscale rescale` can be measured against the truth:
//
//   roadscale_destroy_scale --gt ../shared/kitti/poses/00.txt
//       --times ../shared/kitti/sequences/00/times.txt --poses 200 --every 3 --seed 1
//       --out /tmp/ext_00_k3.txt
//
// Writes a TUM file (timestamps from --times, else 10 Hz) or, with --format kitti, KITTI rows
// (only with --every 1: KITTI rows carry no timestamps, so row i must be frame i).
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "roadscale/eval/scale_drift.h"
#include "roadscale/io/kitti_calib.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/util/error.h"

namespace {

int Run(int argc, char** argv) {
  std::string gt_path;
  std::string times_path;
  size_t poses = 0;
  size_t every = 1;
  std::string format = "tum";
  std::string out;
  roadscale::ScaleDriftOptions drift;
  CLI::App app{"Destroy the scale of a ground-truth trajectory with a seeded, drifting factor"};
  app.add_option("--gt", gt_path, "Ground-truth trajectory, KITTI rows")->required();
  app.add_option("--times", times_path,
                 "KITTI times.txt with one timestamp per ground-truth row (default: 10 Hz)");
  app.add_option("--poses", poses, "Use the first N poses (default: all)");
  app.add_option("--every", every, "Keep every N-th pose (keyframes)")->capture_default_str();
  app.add_option("--seed", drift.seed, "Seed of the drift's random walk")->capture_default_str();
  app.add_option("--initial-scale", drift.initial_scale, "Scale factor at the start")
      ->capture_default_str();
  app.add_option("--growth", drift.growth_per_step, "Growth of log(scale) per frame")
      ->capture_default_str();
  app.add_option("--sigma", drift.random_walk_sigma, "Random walk of log(scale) per frame")
      ->capture_default_str();
  app.add_option("--format", format, "tum or kitti")->capture_default_str();
  app.add_option("--out", out, "Output trajectory file")->required();
  CLI11_PARSE(app, argc, argv);

  roadscale::Trajectory gt = roadscale::ReadKittiTrajectory(gt_path);
  if (!times_path.empty()) {
    gt.timestamps = roadscale::ReadKittiTimes(times_path);
    if (gt.timestamps.size() < gt.size()) {
      roadscale::ThrowFileError(times_path, "has fewer timestamps than " + gt_path + " has poses");
    }
    gt.timestamps.resize(gt.size());
  } else {
    for (size_t k = 0; k < gt.size(); ++k) gt.timestamps.push_back(0.1 * static_cast<double>(k));
  }
  if (poses > 0 && poses < gt.size()) {
    gt.world_from_cam.resize(poses);
    gt.timestamps.resize(poses);
  }
  const roadscale::Trajectory external =
      roadscale::KeepEveryNthPose(roadscale::DistortTrajectoryScale(gt, drift), every);
  const roadscale::TrajectoryFormat out_format = roadscale::ParseTrajectoryFormat(format);
  if (out_format == roadscale::TrajectoryFormat::kKitti) {
    if (every != 1) throw roadscale::Error("--format kitti needs --every 1 (rows are frames)");
    roadscale::WriteKittiTrajectory(out, external);
  } else {
    roadscale::WriteTumTrajectory(out, external);
  }
  std::cout << out << ": " << external.size() << " poses, scale "
            << roadscale::ScaleDriftFactors(gt.size(), drift).back() << " at the last frame\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const roadscale::Error& e) {
    std::cerr << "roadscale_destroy_scale: error: " << e.what() << '\n';
    return 1;
  }
}
