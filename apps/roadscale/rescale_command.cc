// `roadscale rescale`: the scale module serving any visual odometry. Takes another VO's
// trajectory (arbitrary, drifting scale; keyframes only is fine), keeps its rotations and
// translation directions, and gives every step its metric length from the road plane.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "roadscale/config/config_yaml.h"
#include "roadscale/config/rescale_config.h"
#include "roadscale/eval/trajectory_evaluation.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/odometry/odometry_config.h"
#include "roadscale/rescale/rescale_agreement.h"
#include "roadscale/rescale/trajectory_rescaler.h"
#include "roadscale/util/error.h"
#include "roadscale/util/line_file.h"

#include "commands.h"
#include "interrupt.h"
#include "output_folder.h"
#include "run_command.h"

namespace roadscale::cli {
namespace {

namespace fs = std::filesystem;

struct RescaleArguments {
  std::string trajectory;
  std::string format;
  std::string kitti;
  std::string images;
  std::string camera;
  std::string model;
  std::string labels;
  bool no_segmentation = false;
  std::optional<double> h0;
  double max_time_diff = 0.01;
  std::string detector = DetectorTypeName(TrajectoryRescalerOptions().tracker.detector.type);
  bool no_refine = false;
  bool smooth_ratio = false;
  int span_steps = TrajectoryRescalerOptions().max_span_steps;
  std::string config;
  std::string out;
};

// The trajectory, read once (a pipe works): in --format's format, else in the one its first
// row has (KITTI: 12 numbers, TUM: 8).
Trajectory ReadExternalTrajectory(const RescaleArguments& arguments, TrajectoryFormat* format) {
  if (arguments.format.empty()) return ReadTrajectoryOfEitherFormat(arguments.trajectory, format);
  *format = ParseTrajectoryFormat(arguments.format);
  return ReadTrajectory(arguments.trajectory, *format);
}

// The pose frames' segmenter, built by the library as `roadscale run` builds its own: the
// label images, a model (the default network when its files are there, else none, said so),
// or none.
std::unique_ptr<Segmenter> OpenSegmenter(const RescaleArguments& arguments,
                                         std::string* description) {
  RunConfig config;
  config.labels = arguments.labels;
  if (arguments.no_segmentation) config.segmentation.model = "none";
  if (!arguments.model.empty()) config.segmentation.model = arguments.model;
  // One network, the pose frames in turn: one copy, both cores for its inference.
  config.segmentation.workers = 1;
  config.segmentation.dnn_threads = 2;
  const std::string fallback = ResolveDefaultModel(DefaultModelPath(), &config);
  if (!fallback.empty()) std::cerr << "roadscale: " << fallback << '\n';
  std::vector<std::unique_ptr<Segmenter>> segmenters = MakeConfigSegmenters(config);
  if (segmenters.empty()) {
    *description = arguments.no_segmentation ? "none (--no-segmentation)"
                                             : "none (the default model is missing)";
    return nullptr;
  }
  *description = segmenters.front()->Description();
  return std::move(segmenters.front());
}

std::ofstream OpenOutput(const std::string& path) {
  std::ofstream file(path);
  if (!file) ThrowFileError(path, "cannot create this file");
  return file;
}

// One row, flushed at once so that the rows stay intact whatever stops the run.
void WriteRow(std::ofstream& file, const fs::path& path, const std::string& row) {
  WriteWholeLine(file, path.string(), row);
}

std::string Fixed(double value, int digits) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << value;
  return text.str();
}

// One line of the evaluation summary: length ratio, KITTI t_err on 100 m, ATE.
std::string SummaryLine(const std::string& name, const TrajectoryEvaluation& evaluation) {
  std::ostringstream line;
  line << "  " << std::left << std::setw(10) << name << std::right << std::setw(13)
       << (evaluation.errors.length_ratio ? Fixed(*evaluation.errors.length_ratio, 4) : "-");
  const KittiLengthResult& l100 = evaluation.kitti.per_length.front();
  line << std::setw(16)
       << (l100.t_err
               ? Fixed(100.0 * *l100.t_err, 2) + " % (" + std::to_string(l100.n_segments) + ")"
               : "no segment");
  line << std::setw(12) << Fixed(evaluation.errors.ate_se3_m, 3) << std::setw(12)
       << (evaluation.errors.ate_sim3_m ? Fixed(*evaluation.errors.ate_sim3_m, 3) : "-") << '\n';
  return line.str();
}

// Says how the input's step lengths compare with the road's fixes, and warns when the chosen
// ratio is the one that loses (MeasureInputAgreement).
void ReportAgreement(const InputAgreement& agreement, bool step_own_ratio) {
  const auto percent = [](double log_ratio) { return Fixed(100.0 * log_ratio, 1) + " %"; };
  std::cout << "Agreement:  the input's steps against the road vary " +
                   percent(agreement.step_spread) +
                   " from step to step, the road fixes' own "
                   "noise is " +
                   percent(agreement.fix_noise) + " ("
            << agreement.step_pairs << " and " << agreement.fix_pairs << " steps)\n";
  if (agreement.InputAsGoodAsTheRoad() && step_own_ratio) {
    std::cerr << "roadscale: warning: the input's step lengths agree with the road to within "
                 "the road fixes' own noise: taking each step's own road ratio adds that noise "
                 "to a good input; --smooth-ratio keeps its lengths up to a slowly varying "
                 "scale\n";
  } else if (!agreement.InputAsGoodAsTheRoad() && !step_own_ratio) {
    std::cerr << "roadscale: warning: the input's step lengths vary by about "
              << percent(agreement.InputStepError())
              << " a step beyond the road fixes' noise: --smooth-ratio keeps those errors, "
                 "the default takes each step's own road ratio\n";
  }
}

void RunRescale(const RescaleArguments& arguments) {
  TrajectoryRescalerOptions options = RescalerOptionsFromConfig(arguments.config);
  CheckOption(std::isfinite(arguments.max_time_diff) && arguments.max_time_diff >= 0.0,
              "--max-time-diff", "must be a non-negative number of seconds");
  options.tracker.detector.type = ParseDetectorType(arguments.detector);
  options.refine_motion = !arguments.no_refine;
  options.step_own_ratio = !arguments.smooth_ratio;
  CheckOption(arguments.span_steps >= 1, "--span-steps",
              "must be >= 1 (1: each step's own pair only)");
  options.max_span_steps = arguments.span_steps;
  TrajectoryFormat format = TrajectoryFormat::kKitti;
  const Trajectory external = ReadExternalTrajectory(arguments, &format);
  if (external.size() == 0) ThrowFileError(arguments.trajectory, "no poses in the file");

  FrameSourceOptions source_options;
  source_options.input = arguments.kitti.empty() ? arguments.images : arguments.kitti;
  source_options.camera_yaml = arguments.camera;
  source_options.h0 = arguments.h0;
  source_options.Check();
  std::unique_ptr<ImageFileSequence> source;
  if (!arguments.kitti.empty()) {
    source_options.type = FrameSourceType::kKitti;
    source = std::make_unique<KittiSequence>(source_options);
  } else {
    source_options.type = FrameSourceType::kImageFolder;
    source = std::make_unique<ImageFolder>(source_options);
  }
  options.scale.camera_height = source->camera().h0;
  options.Check();

  const std::vector<size_t> pose_frames = AssociatePosesWithFrames(
      external, arguments.trajectory, source->timestamps(), arguments.max_time_diff);

  // Every check that can fail on the segmentation runs before the first frame.
  std::string segmentation_description;
  std::unique_ptr<Segmenter> segmenter = OpenSegmenter(arguments, &segmentation_description);
  if (segmenter) {
    std::vector<std::string> names;
    for (size_t position : pose_frames) {
      names.push_back(fs::path(source->image_paths()[position]).stem().string());
    }
    const PinholeCamera& camera = source->camera().camera;
    segmenter->CheckFrames(names, cv::Size(camera.width, camera.height));
  }

  const fs::path out(arguments.out);
  const FolderLock lock = PrepareOutputFolder(arguments.out, "rescale");
  std::ofstream kitti_file = OpenOutput((out / "poses_kitti.txt").string());
  std::ofstream tum_file = OpenOutput((out / "poses_tum.txt").string());
  std::ofstream csv_file = OpenOutput((out / "rescale.csv").string());
  WriteRow(csv_file, out / "rescale.csv", RescaleCsvHeader());

  std::cout << "Input:      " << source->Describe() << '\n'
            << "Trajectory: " << arguments.trajectory << " ("
            << (format == TrajectoryFormat::kTum ? "TUM" : "KITTI") << ", " << external.size()
            << " poses " << (external.HasTimestamps() ? "associated by time with" : "on")
            << " frames " << pose_frames.front() << ".." << pose_frames.back() << " of "
            << source->size() << ")\n"
            << "Scale:      road plane, h0 = " << source->camera().h0 << " m, "
            << arguments.detector << " features"
            << (options.refine_motion ? ", motion refined on the tracks" : "") << '\n'
            << "Segmentation: " << segmentation_description << '\n';
  for (const std::string& note : source->notes()) std::cerr << "roadscale: note: " << note << '\n';

  TrajectoryRescaler rescaler(source->camera().camera, external, pose_frames, options);
  Trajectory rescaled;
  std::map<RescaleStatus, int> counts;
  int span_fixed = 0;  // ok over a span of steps (TrajectoryRescalerOptions::max_span_steps)
  std::vector<RescaledPose> measured;  // without their point lists, for MeasureInputAgreement
  double total_ms = 0.0;
  const InterruptScope interrupt_scope;
  const auto on_pose = [&](const RescaledPose& pose) {
    WriteRow(kitti_file, out / "poses_kitti.txt", FormatKittiRow(pose.world_from_cam));
    WriteRow(tum_file, out / "poses_tum.txt", FormatTumRow(pose.timestamp, pose.world_from_cam));
    if (pose.status != RescaleStatus::kFirst) {
      WriteRow(csv_file, out / "rescale.csv", FormatRescaleCsv(pose));
      ++counts[pose.status];
      if (pose.status == RescaleStatus::kOk && pose.road_steps > 1) ++span_fixed;
      total_ms += pose.total_ms;
      measured.push_back(pose);
      measured.back().estimate = ScaleEstimate();
    }
    rescaled.world_from_cam.push_back(pose.world_from_cam);
    rescaled.timestamps.push_back(pose.timestamp);
  };
  if (RunTrajectoryRescaler(*source, segmenter.get(), rescaler, on_pose,
                            &InterruptScope::interrupted())) {
    throw Error("interrupted after " + std::to_string(rescaled.size()) + " of " +
                std::to_string(external.size()) + " poses: " + (out / "poses_kitti.txt").string() +
                ", poses_tum.txt and rescale.csv hold those poses");
  }

  const size_t steps = external.size() - 1;
  std::cout << "Steps:      " << steps << " (";
  bool first = true;
  for (const auto& [status, count] : counts) {
    std::cout << (first ? "" : ", ") << count << ' ' << RescaleStatusName(status);
    if (status == RescaleStatus::kOk && span_fixed > 0) {
      std::cout << " (" << span_fixed << " of them over a span of steps)";
    }
    first = false;
  }
  std::cout << "), " << Fixed(total_ms / static_cast<double>(steps), 1) << " ms a step\n";
  if (counts[RescaleStatus::kUnscaled] > 0) {
    std::cerr << "roadscale: warning: no road plane was found in any step: the trajectory keeps "
                 "the input's (unscaled) step lengths\n";
  }
  if (const std::optional<InputAgreement> agreement = MeasureInputAgreement(measured)) {
    ReportAgreement(*agreement, options.step_own_ratio);
  }
  std::cout << "Poses:      " << (out / "poses_kitti.txt").string() << ", "
            << (out / "poses_tum.txt").string() << '\n'
            << "Per step:   " << (out / "rescale.csv").string() << '\n';

  const Trajectory* ground_truth = source->ground_truth();
  if (ground_truth == nullptr) return;
  std::vector<Rigid3d> gt;
  std::vector<Rigid3d> input;
  for (size_t k = 0; k < pose_frames.size(); ++k) {
    gt.push_back(ground_truth->world_from_cam[pose_frames[k]]);
    input.push_back(external.world_from_cam[k]);
  }
  std::cout << "Against the ground truth (" << gt.size()
            << " poses; t_err: KITTI metric on 100 m segments, their count in brackets):\n"
            << "             length ratio     t_err 100 m   ATE se3 m  ATE sim3 m\n"
            << SummaryLine("input", EvaluateTrajectory(gt, input))
            << SummaryLine("rescaled", EvaluateTrajectory(gt, rescaled.world_from_cam));
}

}  // namespace

void RegisterRescaleCommand(CLI::App& app) {
  auto arguments = std::make_shared<RescaleArguments>();
  CLI::App* command = app.add_subcommand(
      "rescale",
      "Give another visual odometry's trajectory (e.g. ORB-SLAM3 monocular: arbitrary, drifting "
      "scale, keyframes only) its metric scale from the road plane. Its rotations and "
      "translation directions are kept; for each pair of consecutive poses, features are tracked "
      "between their frames and the road plane gives the step's length in metres (a step "
      "without one is measured over a span of poses, --span-steps). Writes, step "
      "by step: OUT/poses_kitti.txt and OUT/poses_tum.txt (one row per input pose) and "
      "OUT/rescale.csv (per step: frames, input and metric length, status, counts, times); "
      "Ctrl-C or SIGTERM stops after the frame in flight with those files intact and exits 1. "
      "Prints length ratio, KITTI t_err and ATE when the sequence has ground truth.");
  command
      ->add_option("--trajectory", arguments->trajectory,
                   "The other VO's trajectory (world_from_cam): TUM rows (timestamp tx ty tz qx "
                   "qy qz qw) are associated with the frames by time, KITTI rows (12 numbers) "
                   "are frames 0, 1, 2, ...")
      ->required();
  command->add_option("--format", arguments->format,
                      "kitti or tum (default: from the number of numbers in a row)");
  CLI::Option* kitti = command->add_option("--kitti", arguments->kitti,
                                           "KITTI odometry sequence folder (.../sequences/NN)");
  CLI::Option* images =
      command->add_option("--images", arguments->images,
                          "Folder of images (*.png, *.jpg) in natural order, with times.txt "
                          "for timestamps (else 10 Hz)");
  kitti->excludes(images);
  command->add_option("--camera", arguments->camera,
                      "Camera YAML (Camera: fx fy cx cy width height h0); required with --images");
  CLI::Option* model = command->add_option(
      "--model", arguments->model,
      "Segmentation model YAML: road mask and moving objects of every pose's frame "
      "(default: config/models/espnetv2_512x256.yaml, the shared ESPNetv2; without its files "
      "the run goes on without segmentation and says so)");
  CLI::Option* labels =
      command->add_option("--labels", arguments->labels,
                          "Folder of label PNGs (Cityscapes train ids) named like the frames, "
                          "e.g. a synthetic sequence's semantic/ (default: none)");
  CLI::Option* no_segmentation = command->add_flag(
      "--no-segmentation", arguments->no_segmentation,
      "No segmentation: road points found by the geometric checks only (default: off)");
  model->excludes(labels);
  model->excludes(no_segmentation);
  labels->excludes(no_segmentation);
  command->add_option("--h0", arguments->h0,
                      "Camera height above the road in metres (default: --camera's h0, the "
                      "sequence's camera.yaml, else KITTI's 1.65)");
  command
      ->add_option("--max-time-diff", arguments->max_time_diff,
                   "Largest difference in seconds between a pose's timestamp and its frame's")
      ->capture_default_str();
  command
      ->add_option("--detector", arguments->detector,
                   "Feature detector: fast, sift (the paper's frontend's), orb, brisk or akaze "
                   "(fast finds the faint road texture that the scale needs; see "
                   "docs/benchmark-history.md)")
      ->capture_default_str();
  command->add_flag("--smooth-ratio", arguments->smooth_ratio,
                    "Give every step the filtered ratio of metres per input unit (Scale.filter), "
                    "not its own road plane's: for an input whose step lengths are right up to a "
                    "slowly drifting scale (default: off; a step's own ratio where it has a road "
                    "plane, the filtered one where it has none)");
  command
      ->add_option("--span-steps", arguments->span_steps,
                   "A step without a road plane of its own is measured again from up to this "
                   "many poses back, and takes that span's ratio (1: each step's own pair only)")
      ->capture_default_str();
  command->add_flag("--no-refine", arguments->no_refine,
                    "Triangulate with the input's motion as it is, without refining it on the "
                    "tracks (default: refined; the output keeps the input's motion either way)");
  command->add_option("--config", arguments->config,
                      "Run config YAML whose Scale: block and Mapping: road_alignment* keys set "
                      "the road-plane scale's and the road alignment's options "
                      "(config/kitti.yaml lists them; the other keys are not used here; "
                      "default: the defaults of config/kitti.yaml)");
  command
      ->add_option("--out", arguments->out,
                   "Output folder (created when missing). It holds one run: the files a run or "
                   "rescale writes are removed from it first, other files are left alone")
      ->required();
  command->callback([arguments, kitti, images] {
    if (kitti->count() == 0 && images->count() == 0) {
      throw Error("roadscale rescale needs --kitti SEQ_DIR or --images DIR");
    }
    if (images->count() > 0 && arguments->camera.empty()) {
      throw Error("roadscale rescale --images needs --camera CAMERA.yaml");
    }
    RunRescale(*arguments);
  });
}

}  // namespace roadscale::cli
