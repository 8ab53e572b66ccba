// `roadscale run`: the visual odometry on a sequence (the system of the paper's Fig. 1):
// segmentation, frontend and road-plane scale on their own threads, outputs written while
// it runs, a report at the end.
#include "run_command.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <system_error>
#include <utility>

#include <unistd.h>

#include "roadscale/eval/metrics_json.h"
#include "roadscale/frontend/feature_detector.h"
#include "roadscale/odometry/drive.h"
#include "roadscale/util/error.h"

#include "commands.h"
#include "interrupt.h"
#include "output_folder.h"

namespace roadscale::cli {
namespace {

void Note(const std::string& text) { std::cerr << "roadscale: note: " << text << '\n'; }

// run's options merged over its config file, checked before the output folder is touched.
DriveSetup DriveSetupOf(const RunArguments& arguments) {
  const int inputs =
      !arguments.kitti.empty() + !arguments.images.empty() + !arguments.video.empty();
  if (inputs != 1) throw Error("give exactly one of --kitti, --images, --video");
  if (!arguments.model.empty() + !arguments.labels.empty() + arguments.no_segmentation > 1) {
    throw Error("give at most one of --model, --labels, --no-segmentation");
  }
  DriveSetup setup;
  RunConfig& config = setup.config;
  if (!arguments.config.empty()) ReadRunConfig(arguments.config, &config);
  if (arguments.scale) config.scale_source = *arguments.scale;
  if (arguments.detector) {
    config.pipeline.frontend.tracker.detector.type = ParseDetectorType(*arguments.detector);
  }
  if (arguments.h0) config.camera.h0 = *arguments.h0;
  if (!arguments.model.empty()) {
    config.segmentation.model = arguments.model;
    config.labels.clear();
  }
  if (!arguments.labels.empty()) config.labels = arguments.labels;
  if (arguments.no_segmentation) {
    config.segmentation.model = "none";
    config.labels.clear();
  }
  if (config.scale_source != "oracle" && config.scale_source != "road") {
    throw Error("unknown --scale '" + config.scale_source + "' (expected road or oracle)");
  }
  config.pipeline.Check();
  const std::string fallback = ResolveDefaultModel(DefaultModelPath(), &config);
  if (!fallback.empty()) std::cerr << "roadscale: " << fallback << '\n';

  FrameSourceOptions& source = setup.source;
  source.type = !arguments.kitti.empty()    ? FrameSourceType::kKitti
                : !arguments.images.empty() ? FrameSourceType::kImageFolder
                                            : FrameSourceType::kVideo;
  source.input = !arguments.kitti.empty()    ? arguments.kitti
                 : !arguments.images.empty() ? arguments.images
                                             : arguments.video;
  source.frames = ParseFrameRange(arguments.frames);
  source.camera_yaml = arguments.camera;
  setup.out_dir = arguments.out;
  setup.config_name = arguments.config;
  return setup;
}

// The progress line, on a terminal only (logs and CI stay clean).
class ProgressLine {
 public:
  explicit ProgressLine(size_t total) : total_(total), shown_(isatty(STDERR_FILENO) != 0) {}

  void operator()(const FrameRecord& record, const Rigid3d&) {
    ++frames_;
    if (!shown_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_print_ < std::chrono::milliseconds(200) && frames_ != total_) return;
    last_print_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double fps = elapsed > 0.0 ? static_cast<double>(frames_) / elapsed : 0.0;
    const double eta = fps > 0.0 ? static_cast<double>(total_ - frames_) / fps : 0.0;
    std::fprintf(stderr, "\rframe %zu (%zu/%zu)  %.1f fps  step %.3f m (%s)  ETA %.0f s   ",
                 record.index, frames_, total_, fps, record.step_length_m, record.status.c_str(),
                 eta);
    std::fflush(stderr);
  }
  // Ends the line (once).
  void End() {
    if (shown_ && !ended_) std::fprintf(stderr, "\n");
    ended_ = true;
  }
  size_t frames() const { return frames_; }

 private:
  size_t total_;
  bool shown_;
  bool ended_ = false;
  size_t frames_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_print_ = start_;
};

std::string MetricsLine(const TrajectoryEvaluation& e) {
  return "Metrics: KITTI t_err " +
         (e.kitti.t_err ? std::to_string(KittiTErrPercent(*e.kitti.t_err)) + " %"
                        : std::string("n/a (too short)")) +
         ", ATE(se3) " + std::to_string(e.errors.ate_se3_m) + " m, length ratio " +
         (e.errors.length_ratio ? std::to_string(*e.errors.length_ratio) : "n/a") + '\n';
}

}  // namespace

std::string DefaultModelPath() {
  // An installed command takes the model file installed with it (PREFIX/share/roadscale),
  // not the one of a source tree that may have changed or gone since.
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed =
        (program.parent_path() / ROADSCALE_DATA_FROM_BIN / kDefaultSegmentationModel)
            .lexically_normal();
    if (std::filesystem::exists(installed, error)) return installed.string();
  }
  return (std::filesystem::path(ROADSCALE_SOURCE_DIR) / kDefaultSegmentationModel).string();
}

void RunRun(const RunArguments& arguments) {
  DriveSetup setup = DriveSetupOf(arguments);
  const FolderLock lock = PrepareOutputFolder(arguments.out, "run");
  Drive drive(std::move(setup));
  for (const std::string& note : drive.notes()) Note(note);
  std::cout << drive.Describe() << std::flush;

  ProgressLine progress(drive.size());
  PipelineRunResult result;
  {
    InterruptScope interrupt_scope;
    try {
      result = drive.Run(!arguments.sequential, std::ref(progress), &InterruptScope::interrupted());
    } catch (const Error&) {
      progress.End();
      throw;
    }
  }
  progress.End();
  const std::string poses_path = arguments.out + "/poses_kitti.txt";
  if (result.interrupted) {
    throw Error("interrupted after " + std::to_string(progress.frames()) +
                " frames: " + poses_path + ", poses_tum.txt and frames.csv hold those frames");
  }

  const Drive::Report report = drive.WriteReport(arguments.title);
  for (const std::string& warning : report.warnings) {
    std::cerr << "roadscale: warning: " << warning << '\n';
  }
  std::cout << result.summary.Format() << "Poses:  " << poses_path << " (and poses_tum.txt)\n"
            << "Frames: " << arguments.out << "/frames.csv\n"
            << "Config: " << arguments.out << "/config_used.yaml\n";
  if (report.ground_truth_written) {
    std::cout << "Ground truth of these frames: " << arguments.out << "/gt_poses_kitti.txt\n";
  }
  if (report.evaluation) std::cout << MetricsLine(*report.evaluation);
  for (const std::string& path : report.written) std::cout << "Wrote:  " << path << '\n';
}

void RegisterRunCommand(CLI::App& app) {
  auto arguments = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand(
      "run",
      "Run the monocular visual odometry with road-plane scale on a sequence. Writes, while it "
      "runs (a crash, Ctrl-C or SIGTERM leaves the frames before it intact; Ctrl-C and SIGTERM "
      "stop after the frames in flight and exit 1): OUT/poses_kitti.txt (one "
      "world_from_cam row per input frame, the first frame is the world), OUT/poses_tum.txt "
      "(the same with timestamps), OUT/frames.csv (per frame: status, tracks, inliers, ms per "
      "stage, then the keyframe back end's keyframe, localisation, map scale, road points and "
      "bundle adjustment, or with Mapping.mode frame_to_frame the points after each scale stage, "
      "plane n and h, raw and filtered scale; docs/usage.md lists them), "
      "OUT/config_used.yaml (every option; --config it to repeat the run); at the end "
      "OUT/report.html and, with ground truth, OUT/metrics.json and OUT/gt_poses_kitti.txt.");
  command->add_option("--kitti", arguments->kitti,
                      "KITTI odometry sequence folder (.../sequences/NN; ground truth from "
                      "../../poses/NN.txt when present)");
  command->add_option("--images", arguments->images,
                      "Folder of images (png/jpg, in natural order: img9 before img10; numbered "
                      "frames without gaps); needs --camera");
  command->add_option("--video", arguments->video, "Video file; needs --camera");
  command->add_option("--camera", arguments->camera,
                      "Camera YAML (Camera: fx fy cx cy width height h0), for --images/--video");
  command->add_option("--config", arguments->config,
                      "Config YAML with Camera:, Frontend:, Scale:, Segmentation:, Mapping: blocks "
                      "(config/kitti.yaml lists every key with the paper's defaults); command-line "
                      "options override it (default: none, the paper's defaults)");
  command->add_option("--model", arguments->model,
                      "Segmentation model YAML (default: config/models/espnetv2_512x256.yaml with "
                      "the shared network; without it, no segmentation and a note)");
  command->add_option("--labels", arguments->labels,
                      "Folder of precomputed label PNGs (<frame name>.png, Cityscapes train ids) "
                      "instead of a network");
  command->add_flag("--no-segmentation", arguments->no_segmentation,
                    "Run without segmentation: features anywhere, every triangulated point a "
                    "road candidate (the paper's ablation); the keyframe host aligns the road "
                    "where a level road lies ahead instead "
                    "(Mapping.road_alignment_region_distance)");
  command->add_option("--scale", arguments->scale,
                      "Where each step's length comes from: road = the road plane and h0 (the "
                      "paper's method), oracle = the ground truth's step length (default: road, "
                      "or the config's Scale.source)");
  command->add_option("--h0", arguments->h0,
                      "Camera height above the road in metres (default: the config's Camera.h0, "
                      "the camera YAML's, the sequence's camera.yaml, else KITTI's 1.65)");
  command->add_option("--detector", arguments->detector,
                      "Feature detector: sift (the paper's), orb, brisk, akaze or fast (default: "
                      "sift, or the config's Frontend.detector)");
  command->add_option("--frames", arguments->frames,
                      "Frames to process: A:B (A..B-1), A: or :B (default: all)");
  command
      ->add_option("--out", arguments->out,
                   "Output folder (created when missing). It holds one run: the files a run or "
                   "rescale writes are removed from it first, other files are left alone")
      ->required();
  command->add_flag("--sequential", arguments->sequential,
                    "Run the stages one after the other on one thread (same output, slower; "
                    "default: segmentation, frontend and scale on their own threads)");
  command->callback([arguments] { RunRun(*arguments); });
}

}  // namespace roadscale::cli
