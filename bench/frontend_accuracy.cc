// Accuracy and per-stage speed of the monocular frontend with the oracle scale on one
// KITTI-layout sequence (the shared KITTI 00 frames, or a `roadscale synth` sequence): runs
// the sequential pipeline, then compares the written poses with the ground truth.
//
//   roadscale_frontend_accuracy --sequence ../shared/kitti/sequences/00 [--detector sift]
//       [--redetect-below 600] [--no-refine] [--fb 0.5] [--frames A:B] [--out DIR]
//
// Prints one table row: KITTI t_err / r_err on 100 m segments, per-frame rotation error and
// translation-direction error (degrees; from consecutive poses: the step cur_from_prev of the
// estimate against the ground truth's), frame counts by pose update, and mean ms per frame
// of tracking, detection and motion.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "roadscale/eval/kitti_odometry_metric.h"
#include "roadscale/frontend/feature_detector.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/pipeline/oracle_scale_source.h"
#include "roadscale/pipeline/sequential_pipeline.h"
#include "roadscale/util/error.h"

#include <Eigen/Geometry>

namespace {

using roadscale::Rigid3d;

double Percentile(std::vector<double> values, double p) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<size_t>(p * (values.size() - 1) + 0.5))];
}

double Mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return values.empty() ? NAN : sum / static_cast<double>(values.size());
}

constexpr double kDeg = 180.0 / M_PI;

int Run(int argc, char** argv) {
  std::string sequence;
  std::string detector = "sift";
  int redetect_below = roadscale::FeatureTrackerOptions().redetect_below;
  bool no_refine = false;
  double fb = roadscale::KltOptions().max_forward_backward_error_px;
  std::string frames;
  std::string out =
      (std::filesystem::temp_directory_path() / "roadscale_frontend_accuracy").string();
  CLI::App app{"Frontend accuracy with the oracle scale on a KITTI-layout sequence"};
  app.add_option("--sequence", sequence, "KITTI-layout sequence folder")->required();
  app.add_option("--detector", detector, "sift, orb, brisk, akaze or fast")->capture_default_str();
  app.add_option("--redetect-below", redetect_below, "Re-detect below this many tracks")
      ->capture_default_str();
  app.add_flag("--no-refine", no_refine, "Skip the Sampson refinement");
  app.add_option("--fb", fb, "KLT forward-backward threshold (px)")->capture_default_str();
  app.add_option("--frames", frames, "Frames A:B (default: all)");
  app.add_option("--out", out, "Output folder of the run")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  roadscale::PipelineOptions options;
  // The frontend alone: the keyframe host would replace its steps by the map's, which do not
  // take their lengths from the oracle.
  options.mapping.mode = roadscale::MappingOptions::Mode::kFrameToFrame;
  options.frontend.tracker.detector.type = roadscale::ParseDetectorType(detector);
  options.frontend.tracker.redetect_below = redetect_below;
  options.frontend.tracker.klt.max_forward_backward_error_px = fb;
  options.frontend.motion.refine = !no_refine;

  roadscale::FrameSourceOptions source_options;
  source_options.input = sequence;
  source_options.type = roadscale::FrameSourceType::kKitti;
  source_options.frames = roadscale::ParseFrameRange(frames);
  const auto source = roadscale::OpenFrameSource(source_options);
  if (source->ground_truth() == nullptr) throw roadscale::Error(sequence + ": no ground truth");
  const roadscale::Trajectory gt = *source->ground_truth();
  roadscale::OracleScaleSource scale(gt);
  const roadscale::RunSummary summary =
      roadscale::RunSequentialPipeline(*source, scale, options, out);
  const roadscale::Trajectory est = roadscale::ReadKittiTrajectory(out + "/poses_kitti.txt");

  std::vector<double> rotation_errors;
  std::vector<double> direction_errors;
  // Signed means: a bias shows here, noise averages out. Direction: the estimated unit step
  // minus the true one (x right, y down; radians ~ small angles), rotation: the error's
  // axis-angle vector.
  Eigen::Vector3d direction_bias = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_bias = Eigen::Vector3d::Zero();
  for (size_t k = 1; k < gt.size(); ++k) {
    const Rigid3d gt_step = gt.world_from_cam[k].inverse() * gt.world_from_cam[k - 1];
    const Rigid3d est_step = est.world_from_cam[k].inverse() * est.world_from_cam[k - 1];
    const Eigen::Matrix3d rotation_error = est_step.linear().transpose() * gt_step.linear();
    rotation_errors.push_back(roadscale::RotationAngle(rotation_error) * kDeg);
    const Eigen::AngleAxisd axis_angle(rotation_error);
    rotation_bias += axis_angle.angle() * axis_angle.axis();
    // The direction is only defined when both moved; stops are counted by the pose updates.
    if (gt_step.translation().norm() > 0.05 && est_step.translation().norm() > 1e-9) {
      const double c = gt_step.translation().normalized().dot(est_step.translation().normalized());
      direction_errors.push_back(std::acos(std::clamp(c, -1.0, 1.0)) * kDeg);
      direction_bias += est_step.translation().normalized() - gt_step.translation().normalized();
    }
  }
  roadscale::KittiMetricOptions metric;
  metric.lengths_m = {100};
  const roadscale::KittiOdometryResult kitti =
      roadscale::EvaluateKittiOdometry(gt.world_from_cam, est.world_from_cam, metric);

  std::printf(
      "sequence %s frames %zu path %.1f m | detector %s redetect_below %d refine %d fb %.2f\n",
      sequence.c_str(), summary.frames, kitti.gt_path_length_m, detector.c_str(), redetect_below,
      no_refine ? 0 : 1, fb);
  if (kitti.t_err) {
    std::printf("KITTI 100 m: t_err %.3f %%  r_err %.4f deg/m  (%d segments)\n",
                100.0 * *kitti.t_err, *kitti.r_err * kDeg, kitti.n_segments());
  } else {
    std::printf("KITTI 100 m: no segment fits\n");
  }
  std::printf("rotation error per frame [deg]: mean %.4f median %.4f p90 %.4f max %.4f\n",
              Mean(rotation_errors), Percentile(rotation_errors, 0.5),
              Percentile(rotation_errors, 0.9), Percentile(rotation_errors, 1.0));
  std::printf(
      "direction error per frame [deg]: mean %.3f median %.3f p90 %.3f max %.3f (%zu moving "
      "frames)\n",
      Mean(direction_errors), Percentile(direction_errors, 0.5), Percentile(direction_errors, 0.9),
      Percentile(direction_errors, 1.0), direction_errors.size());
  direction_bias *= kDeg / std::max<size_t>(1, direction_errors.size());
  rotation_bias *= kDeg / std::max<size_t>(1, rotation_errors.size());
  std::printf(
      "mean signed errors [deg]: direction (x %.3f, y %.3f)  rotation (x %.4f, y %.4f, z %.4f)\n",
      direction_bias.x(), direction_bias.y(), rotation_bias.x(), rotation_bias.y(),
      rotation_bias.z());
  std::printf("%s", summary.Format().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const roadscale::Error& e) {
    std::cerr << "roadscale_frontend_accuracy: error: " << e.what() << '\n';
    return 1;
  }
}
