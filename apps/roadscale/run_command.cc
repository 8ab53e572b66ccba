// `roadscale run`: the visual odometry on a sequence (the system of the paper's Fig. 1):
// segmentation, frontend and road-plane scale on their own threads, outputs written while
// it runs, a report at the end.
#include "run_command.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

#include <unistd.h>

#include "roadscale/eval/metrics_json.h"
#include "roadscale/frontend/feature_detector.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/odometry/odometry_config.h"
#include "roadscale/pipeline/config_yaml.h"
#include "roadscale/pipeline/oracle_scale_source.h"
#include "roadscale/pipeline/road_scale_source.h"
#include "roadscale/pipeline/run_pipeline.h"
#include "roadscale/pipeline/run_report.h"
#include "roadscale/segmentation/segmentation_model.h"
#include "roadscale/util/error.h"

#include "commands.h"
#include "interrupt.h"
#include "output_folder.h"

namespace roadscale::cli {
namespace {

void Note(const std::string& text) { std::cerr << "roadscale: note: " << text << '\n'; }

// The shared network's model YAML for "default", or no segmentation (with a note) when its
// files are not there; config_used.yaml then says what was used.
void ResolveDefaultModel(RunConfig* config) {
  SegmentationOptions& options = config->segmentation;
  if (!config->labels.empty() || options.model != "default") return;
  const std::string path = DefaultModelPath();
  try {
    ReadSegmentationModel(path);
    options.model = path;
  } catch (const Error& error) {
    std::cerr << "roadscale: segmentation off: model not found at " << path << " (" << error.what()
              << ")\n";
    options.model = "none";
  }
}

std::string Describe(const RunConfig& config, const Segmenter& segmenter) {
  return config.labels.empty() ? segmenter.Description() : "label images in " + config.labels;
}

}  // namespace

std::string DefaultModelPath() {
  return (std::filesystem::path(ROADSCALE_SOURCE_DIR) / kDefaultSegmentationModel).string();
}

void RunRun(const RunArguments& arguments) {
  const int inputs =
      !arguments.kitti.empty() + !arguments.images.empty() + !arguments.video.empty();
  if (inputs != 1) throw Error("give exactly one of --kitti, --images, --video");
  if (!arguments.model.empty() + !arguments.labels.empty() + arguments.no_segmentation > 1) {
    throw Error("give at most one of --model, --labels, --no-segmentation");
  }

  RunConfig config;
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

  const FolderLock lock = PrepareOutputFolder(arguments.out, "run");
  FrameSourceOptions source_options;
  source_options.type = !arguments.kitti.empty()    ? FrameSourceType::kKitti
                        : !arguments.images.empty() ? FrameSourceType::kImageFolder
                                                    : FrameSourceType::kVideo;
  source_options.input = !arguments.kitti.empty()    ? arguments.kitti
                         : !arguments.images.empty() ? arguments.images
                                                     : arguments.video;
  source_options.frames = ParseFrameRange(arguments.frames);
  source_options.h0 = config.camera.h0;
  source_options.camera_yaml = arguments.camera;
  if (source_options.camera_yaml.empty() && config.camera.HasIntrinsics() &&
      source_options.type != FrameSourceType::kKitti) {
    // The config's Camera block is the camera (the camera reader wants every key, h0 too).
    CameraSetup setup;
    setup.camera.fx = *config.camera.fx;
    setup.camera.fy = *config.camera.fy;
    setup.camera.cx = *config.camera.cx;
    setup.camera.cy = *config.camera.cy;
    setup.camera.width = *config.camera.width;
    setup.camera.height = *config.camera.height;
    setup.h0 = config.camera.h0.value_or(1.65);
    setup.distortion = config.camera.Distortion();
    source_options.camera_yaml = (std::filesystem::path(arguments.out) / "camera.yaml").string();
    WriteCameraYaml(source_options.camera_yaml, setup);
  }
  if (source_options.type != FrameSourceType::kKitti && source_options.camera_yaml.empty()) {
    throw Error(
        "--images and --video need --camera CAM.yaml (or a --config with a Camera: "
        "block holding fx, fy, cx, cy, width, height)");
  }
  const std::unique_ptr<FrameSource> source = OpenFrameSource(source_options);
  for (const std::string& note : source->notes()) Note(note);
  const CameraSetup& camera = source->camera();
  config.camera.fx = camera.camera.fx;
  config.camera.fy = camera.camera.fy;
  config.camera.cx = camera.camera.cx;
  config.camera.cy = camera.camera.cy;
  config.camera.width = camera.camera.width;
  config.camera.height = camera.camera.height;
  config.camera.h0 = camera.h0;
  config.camera.SetDistortion(camera.distortion);

  ResolveDefaultModel(&config);
  const std::vector<std::unique_ptr<Segmenter>> owned_segmenters = MakeConfigSegmenters(config);
  NoSegmenter no_segmentation;
  std::vector<Segmenter*> segmenters = Pointers(owned_segmenters);
  if (segmenters.empty()) segmenters.push_back(&no_segmentation);
  Segmenter* segmenter = segmenters.front();
  if (const auto* files = dynamic_cast<const ImageFileSequence*>(source.get())) {
    std::vector<std::string> names;
    for (const std::string& path : files->image_paths()) {
      Frame frame;
      frame.path = path;
      names.push_back(FrameName(frame));
    }
    segmenter->CheckFrames(names, cv::Size(camera.camera.width, camera.camera.height));
  }

  const Trajectory* ground_truth = source->ground_truth();
  std::unique_ptr<ScaleSource> scale_source;
  if (config.scale_source == "oracle") {
    if (ground_truth == nullptr) {
      throw Error(source_options.input +
                  ": --scale oracle needs ground-truth poses (../../poses/NN.txt beside the "
                  "sequence folder), and there are none");
    }
    scale_source = std::make_unique<OracleScaleSource>(*ground_truth);
    // The oracle gives each frame pair's length: only the frame-to-frame host asks for them.
    config.pipeline.mapping.mode = MappingOptions::Mode::kFrameToFrame;
  } else {
    ScaleEstimatorOptions scale_options = config.scale;
    scale_options.camera_height = camera.h0;
    scale_source = std::make_unique<RoadScaleSource>(camera.camera, scale_options);
  }
  const OdometryOptions odometry = OdometryOptionsFromConfig(config, camera);
  const bool keyframe_mode = config.pipeline.mapping.mode == MappingOptions::Mode::kKeyframe;

  const std::string config_path =
      (std::filesystem::path(arguments.out) / "config_used.yaml").string();
  WriteRunConfig(config_path, config);
  const std::string segmentation_text = Describe(config, *segmenter);
  std::cout << "Input:  " << source->Describe() << '\n'
            << "Scale:  " << scale_source->Name()
            << (config.scale_source == "road" ? " (h0 = " + std::to_string(camera.h0) + " m)"
                                              : std::string())
            << '\n'
            << "Mapping: " << MappingModeName(config.pipeline.mapping.mode)
            << (keyframe_mode
                    ? " (window of " + std::to_string(config.pipeline.mapping.window_size) +
                          " keyframes; rows are written as they leave it)"
                    : std::string())
            << '\n'
            << "Frontend: " << DetectorTypeName(config.pipeline.frontend.tracker.detector.type)
            << " features\n"
            << "Segmentation: " << segmentation_text << " (schedule "
            << SegmentationScheduleModeName(config.pipeline.segmentation_schedule.mode) << ")\n"
            << std::flush;

  // The progress line, on a terminal only (logs and CI stay clean).
  const bool progress = isatty(STDERR_FILENO) != 0;
  const size_t total = source->size();
  const auto start = std::chrono::steady_clock::now();
  auto last_print = start;
  std::vector<FrameRecord> records;
  std::vector<Rigid3d> world_from_cam;
  const auto on_frame = [&](const FrameRecord& record, const Rigid3d& pose) {
    records.push_back(record);
    world_from_cam.push_back(pose);
    if (!progress) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_print < std::chrono::milliseconds(200) && records.size() != total) return;
    last_print = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const double fps = elapsed > 0.0 ? static_cast<double>(records.size()) / elapsed : 0.0;
    const double eta = fps > 0.0 ? static_cast<double>(total - records.size()) / fps : 0.0;
    std::fprintf(stderr, "\rframe %zu (%zu/%zu)  %.1f fps  step %.3f m (%s)  ETA %.0f s   ",
                 record.index, records.size(), total, fps, record.step_length_m,
                 record.status.c_str(), eta);
    std::fflush(stderr);
  };

  PipelineRunResult result;
  {
    InterruptScope interrupt_scope;
    RunPipelineOptions run_options = odometry.run;
    run_options.threaded = !arguments.sequential;
    try {
      result = RunPipeline(*source, segmenters, *scale_source, odometry.pipeline, arguments.out,
                           run_options, on_frame, &InterruptScope::interrupted());
    } catch (const Error&) {
      if (progress) std::fprintf(stderr, "\n");
      throw;
    }
  }
  if (progress) std::fprintf(stderr, "\n");
  const std::string poses_path = arguments.out + "/poses_kitti.txt";
  if (result.interrupted) {
    throw Error("interrupted after " + std::to_string(records.size()) + " frames: " + poses_path +
                ", poses_tum.txt and frames.csv hold those frames");
  }

  RunReportData report;
  report.title = arguments.title.empty() ? "roadscale run: " + source->Describe() : arguments.title;
  report.inputs = {
      {"input", source->Describe()},
      {"camera",
       "fx " + std::to_string(camera.camera.fx) + ", " + std::to_string(camera.camera.width) + "x" +
           std::to_string(camera.camera.height) + ", h0 " + std::to_string(camera.h0) + " m"},
      {"config", arguments.config.empty() ? "defaults" : arguments.config},
      {"segmentation", segmentation_text},
      {"scale", scale_source->Name()},
      {"mapping", MappingModeName(config.pipeline.mapping.mode)},
      {"segmented frames",
       std::to_string(result.summary.segmented_frames) + " of " +
           std::to_string(result.summary.frames) + " (schedule " +
           SegmentationScheduleModeName(config.pipeline.segmentation_schedule.mode) + ")"}};
  report.records = std::move(records);
  report.scale_diagnostics_header =
      keyframe_mode ? MappedFrameCsvHeader() : scale_source->DiagnosticsCsvHeader();
  report.est_world_from_cam = std::move(world_from_cam);
  report.wall_time_s = result.summary.wall_s;
  if (ground_truth != nullptr && ground_truth->world_from_cam.size() >= report.records.size()) {
    Trajectory gt = *ground_truth;
    gt.world_from_cam.resize(report.records.size());
    if (gt.timestamps.size() > report.records.size()) gt.timestamps.resize(report.records.size());
    report.gt_world_from_cam = gt.world_from_cam;
    WriteKittiTrajectory(arguments.out + "/gt_poses_kitti.txt", gt);
  }
  const std::optional<TrajectoryEvaluation> evaluation = EvaluateRun(report);
  const std::vector<std::string> written = WriteRunReport(arguments.out, report, evaluation);
  for (const std::string& warning : ScaleWarnings(report.records)) {
    std::cerr << "roadscale: warning: " << warning << '\n';
  }

  std::cout << result.summary.Format() << "Poses:  " << poses_path << " (and poses_tum.txt)\n"
            << "Frames: " << arguments.out << "/frames.csv\n"
            << "Config: " << config_path << '\n';
  if (!report.gt_world_from_cam.empty()) {
    std::cout << "Ground truth of these frames: " << arguments.out << "/gt_poses_kitti.txt\n";
  }
  if (evaluation) {
    const TrajectoryEvaluation& e = *evaluation;
    std::cout << "Metrics: KITTI t_err "
              << (e.kitti.t_err ? std::to_string(KittiTErrPercent(*e.kitti.t_err)) + " %"
                                : std::string("n/a (too short)"))
              << ", ATE(se3) " << e.errors.ate_se3_m << " m, length ratio "
              << (e.errors.length_ratio ? std::to_string(*e.errors.length_ratio) : "n/a") << '\n';
  }
  for (const std::string& path : written) std::cout << "Wrote:  " << path << '\n';
}

void RegisterRunCommand(CLI::App& app) {
  auto arguments = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand(
      "run",
      "Run the monocular visual odometry with road-plane scale on a sequence. Writes, while it "
      "runs (a crash, Ctrl-C or SIGTERM leaves the frames before it intact; Ctrl-C and SIGTERM "
      "stop after the frames in flight and exit 1): OUT/poses_kitti.txt (one "
      "world_from_cam row per input frame, the first frame is the world), OUT/poses_tum.txt "
      "(the same with timestamps), OUT/frames.csv (per frame: status, tracks, inliers, points "
      "after each scale stage, plane n and h, raw and filtered scale, ms per stage), "
      "OUT/config_used.yaml (every option; --config it to repeat the run); at the end "
      "OUT/report.html and, with ground truth, OUT/metrics.json and OUT/gt_poses_kitti.txt.");
  command->add_option("--kitti", arguments->kitti,
                      "KITTI odometry sequence folder (.../sequences/NN; ground truth from "
                      "../../poses/NN.txt when present)");
  command->add_option("--images", arguments->images,
                      "Folder of images (png/jpg, sorted by name); needs --camera");
  command->add_option("--video", arguments->video, "Video file; needs --camera");
  command->add_option("--camera", arguments->camera,
                      "Camera YAML (Camera: fx fy cx cy width height h0), for --images/--video");
  command->add_option("--config", arguments->config,
                      "Config YAML with Camera:, Frontend:, Scale:, Segmentation: blocks "
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
