#include "roadscale/odometry/drive.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "roadscale/frontend/feature_detector.h"
#include "roadscale/io/camera_setup.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/mapping/keyframe_backend.h"
#include "roadscale/odometry/odometry_config.h"
#include "roadscale/pipeline/oracle_scale_source.h"
#include "roadscale/pipeline/road_scale_source.h"
#include "roadscale/report/run_report.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// The config's Camera block as a camera YAML at `path`, for an input without one.
void WriteConfigCamera(const RunConfig::Camera& camera, const std::string& path) {
  CameraSetup setup;
  setup.camera.fx = *camera.fx;
  setup.camera.fy = *camera.fy;
  setup.camera.cx = *camera.cx;
  setup.camera.cy = *camera.cy;
  setup.camera.width = *camera.width;
  setup.camera.height = *camera.height;
  setup.h0 = camera.h0.value_or(1.65);
  setup.distortion = camera.Distortion();
  WriteCameraYaml(path, setup);
}

std::string OutPath(const DriveSetup& setup, const char* name) {
  return (std::filesystem::path(setup.out_dir) / name).string();
}

}  // namespace

Drive::Drive(DriveSetup setup) : setup_(std::move(setup)) {
  RunConfig& config = setup_.config;
  FrameSourceOptions& source_options = setup_.source;
  if (config.scale_source != "oracle" && config.scale_source != "road") {
    throw Error("unknown --scale '" + config.scale_source + "' (expected road or oracle)");
  }
  config.pipeline.Check();
  source_options.h0 = config.camera.h0;
  if (source_options.camera_yaml.empty() && config.camera.HasIntrinsics() &&
      source_options.type != FrameSourceType::kKitti) {
    source_options.camera_yaml = OutPath(setup_, "camera.yaml");
    WriteConfigCamera(config.camera, source_options.camera_yaml);
  }
  if (source_options.type != FrameSourceType::kKitti && source_options.camera_yaml.empty()) {
    throw Error(
        "--images and --video need --camera CAM.yaml (or a --config with a Camera: "
        "block holding fx, fy, cx, cy, width, height)");
  }
  source_ = OpenFrameSource(source_options);
  const CameraSetup& camera = source_->camera();
  config.camera.fx = camera.camera.fx;
  config.camera.fy = camera.camera.fy;
  config.camera.cx = camera.camera.cx;
  config.camera.cy = camera.camera.cy;
  config.camera.width = camera.camera.width;
  config.camera.height = camera.camera.height;
  config.camera.h0 = camera.h0;
  config.camera.SetDistortion(camera.distortion);

  owned_segmenters_ = MakeConfigSegmenters(config);
  segmenters_ = Pointers(owned_segmenters_);
  if (segmenters_.empty()) segmenters_.push_back(&no_segmentation_);
  if (const auto* files = dynamic_cast<const ImageFileSequence*>(source_.get())) {
    std::vector<std::string> names;
    for (const std::string& path : files->image_paths()) {
      Frame frame;
      frame.path = path;
      names.push_back(FrameName(frame));
    }
    segmenters_.front()->CheckFrames(names, cv::Size(camera.camera.width, camera.camera.height));
  }
  segmentation_text_ = config.labels.empty() ? segmenters_.front()->Description()
                                             : "label images in " + config.labels;

  if (config.scale_source == "oracle") {
    const Trajectory* ground_truth = source_->ground_truth();
    if (ground_truth == nullptr) {
      throw Error(source_options.input +
                  ": --scale oracle needs ground-truth poses (../../poses/NN.txt beside the "
                  "sequence folder), and there are none");
    }
    scale_source_ = std::make_unique<OracleScaleSource>(*ground_truth);
    // The oracle gives each frame pair's length: only the frame-to-frame host asks for them.
    config.pipeline.mapping.mode = MappingOptions::Mode::kFrameToFrame;
  } else {
    ScaleEstimatorOptions scale_options = config.scale;
    scale_options.camera_height = camera.h0;
    scale_source_ = std::make_unique<RoadScaleSource>(camera.camera, scale_options);
  }
  odometry_ = OdometryOptionsFromConfig(config, camera);
  WriteRunConfig(OutPath(setup_, "config_used.yaml"), config);
}

Drive::~Drive() = default;

std::string Drive::Describe() const {
  const RunConfig& config = setup_.config;
  const MappingOptions& mapping = config.pipeline.mapping;
  const bool keyframe_mode = mapping.mode == MappingOptions::Mode::kKeyframe;
  return "Input:  " + source_->Describe() + "\nScale:  " + scale_source_->Name() +
         (config.scale_source == "road" ? " (h0 = " + std::to_string(source_->camera().h0) + " m)"
                                        : std::string()) +
         "\nMapping: " + MappingModeName(mapping.mode) +
         (keyframe_mode ? " (window of " + std::to_string(mapping.window_size) +
                              " keyframes; rows are written as they leave it)"
                        : std::string()) +
         "\nFrontend: " + DetectorTypeName(config.pipeline.frontend.tracker.detector.type) +
         " features\nSegmentation: " + segmentation_text_ + " (schedule " +
         SegmentationScheduleModeName(config.pipeline.segmentation_schedule.mode) + ")\n";
}

PipelineRunResult Drive::Run(bool threaded, const FrameOutput& on_frame,
                             const std::atomic<bool>* stop) {
  RunPipelineOptions run_options = odometry_.run;
  run_options.threaded = threaded;
  records_.clear();
  world_from_cam_.clear();
  result_ = RunPipeline(
      *source_, segmenters_, *scale_source_, odometry_.pipeline, setup_.out_dir, run_options,
      [&](const FrameRecord& record, const Rigid3d& world_from_cam) {
        records_.push_back(record);
        world_from_cam_.push_back(world_from_cam);
        if (on_frame) on_frame(record, world_from_cam);
      },
      stop);
  return result_;
}

Drive::Report Drive::WriteReport(const std::string& title) const {
  const RunConfig& config = setup_.config;
  const CameraSetup& camera = source_->camera();
  const bool keyframe_mode = config.pipeline.mapping.mode == MappingOptions::Mode::kKeyframe;
  // The ground truth of the frames run, when the input has a pose for each of them.
  Trajectory gt;
  const Trajectory* ground_truth = source_->ground_truth();
  const size_t frames = records_.size();
  const bool with_ground_truth =
      ground_truth != nullptr && ground_truth->world_from_cam.size() >= frames;
  if (with_ground_truth) {
    const auto& poses = ground_truth->world_from_cam;
    gt.world_from_cam.assign(poses.begin(), poses.begin() + frames);
    const auto& times = ground_truth->timestamps;
    gt.timestamps.assign(times.begin(), times.begin() + std::min(frames, times.size()));
  }
  RunReportData data(records_, world_from_cam_, gt.world_from_cam);
  data.title = title.empty() ? "roadscale run: " + source_->Describe() : title;
  data.inputs = {
      {"input", source_->Describe()},
      {"camera",
       "fx " + std::to_string(camera.camera.fx) + ", " + std::to_string(camera.camera.width) + "x" +
           std::to_string(camera.camera.height) + ", h0 " + std::to_string(camera.h0) + " m"},
      {"config", setup_.config_name.empty() ? "defaults" : setup_.config_name},
      {"segmentation", segmentation_text_},
      {"scale", scale_source_->Name()},
      {"mapping", MappingModeName(config.pipeline.mapping.mode)},
      {"segmented frames",
       std::to_string(result_.summary.segmented_frames) + " of " +
           std::to_string(result_.summary.frames) + " (schedule " +
           SegmentationScheduleModeName(config.pipeline.segmentation_schedule.mode) + ")"}};
  data.scale_diagnostics_header =
      keyframe_mode ? MappedFrameCsvHeader() : scale_source_->DiagnosticsCsvHeader();
  data.wall_time_s = result_.summary.wall_s;
  Report report;
  if (with_ground_truth) {
    WriteKittiTrajectory(OutPath(setup_, "gt_poses_kitti.txt"), gt);
    report.ground_truth_written = true;
  }
  report.evaluation = EvaluateRun(data);
  report.written = WriteRunReport(setup_.out_dir, data, report.evaluation);
  report.warnings = ScaleWarnings(data.records);
  return report;
}

}  // namespace roadscale
