#include "roadscale/pipeline/sequential_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "roadscale/io/pose_row_check.h"
#include "roadscale/pipeline/run_pipeline.h"
#include "roadscale/pipeline/thread_cpu_time.h"
#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/util/elapsed_time.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using Clock = std::chrono::steady_clock;

// A pose the trajectory readers would reject (eval, rescale, the run's own report) never
// reaches the output: the run stops with an error naming the frame, the rows before it intact.
void CheckPoseToOutput(const Rigid3d& world_from_cam, const FrameRecord& record) {
  const Eigen::Vector3d& position = world_from_cam.translation();
  if (world_from_cam.matrix().allFinite() && position.cwiseAbs().maxCoeff() <= kMaxTranslationM) {
    return;
  }
  char text[240];
  std::snprintf(
      text, sizeof(text),
      "frame %zu: the pose would be at (%.3g, %.3g, %.3g) m, beyond %g m, after a step of "
      "%.3g m (%s): not written",
      record.index, position.x(), position.y(), position.z(), kMaxTranslationM,
      record.step_length_m, record.scale_status.c_str());
  throw Error(text);
}

}  // namespace

void PipelineOptions::Check() const {
  frontend.Check();
  mapping.Check();
  road_selection.Check();
  segmentation_schedule.Check();
  CheckOption(max_frames_before_first_scale >= 0, "scale.max_frames_before_first_scale",
              "must be >= 0 (0: never wait for the first scale)");
}

std::string FrameRecordCsvHeader() {
  return "index,timestamp,motion_status,pose_update,tracks,correspondences,inliers,detected,"
         "dropped_dynamic,road_mask_px,road_tracks,inlier_ratio,flow_px,parallax_px,scale_valid,"
         "step_length_m,scale_status,status,load_ms,segmentation_ms,tracking_ms,detection_ms,"
         "motion_ms,scale_ms,total_ms,segmented,segmentation_cpu_ms,frontend_cpu_ms,scale_cpu_ms";
}

std::string FormatFrameRecordCsv(const FrameRecord& r) {
  std::ostringstream out;
  out << r.index << ',' << std::setprecision(17) << r.timestamp << ',' << std::setprecision(6)
      << MotionStatusName(r.motion_status) << ',' << PoseUpdateName(r.pose_update) << ','
      << r.num_tracks << ',' << r.num_correspondences << ',' << r.num_inliers << ','
      << r.num_detected << ',' << r.num_dropped_dynamic << ',' << r.road_mask_px << ','
      << r.road_tracks << ',' << r.inlier_ratio << ',' << r.flow_px << ',' << r.parallax_px << ','
      << (r.scale_valid ? 1 : 0) << ',' << std::setprecision(9) << r.step_length_m << ','
      << std::setprecision(6) << '"' << r.scale_status << '"' << ',' << r.status << ',' << r.load_ms
      << ',' << r.segmentation_ms << ',' << r.tracking_ms << ',' << r.detection_ms << ','
      << r.motion_ms << ',' << r.scale_ms << ',' << r.total_ms << ',' << (r.segmented ? 1 : 0)
      << ',' << r.segmentation_cpu_ms << ',' << r.frontend_cpu_ms << ',' << r.scale_cpu_ms;
  return out.str();
}

void SetRoadMask(const cv::Mat& road_mask, TrackedFrame* tracked) {
  tracked->road_mask = road_mask;
  if (road_mask.empty()) return;
  tracked->record.road_mask_px = cv::countNonZero(road_mask);
  int on_road = 0;
  for (const TrackObservation& observation : tracked->frontend.observations) {
    if (PixelOnMask(road_mask, observation.pixel)) ++on_road;
  }
  tracked->record.road_tracks = on_road;
}

SequentialPipeline::SequentialPipeline(const CameraSetup& camera, ScaleSource& scale,
                                       const PipelineOptions& options)
    : scale_(scale),
      backend_(options.mapping.mode == MappingOptions::Mode::kKeyframe
                   ? std::make_unique<KeyframeBackend>(
                         camera.camera, options.road_selection.camera_height, options.mapping,
                         options.road_selection, options.frontend.motion,
                         options.max_frames_before_first_scale)
                   : nullptr),
      frontend_(camera.camera, options.frontend),
      max_waiting_frames_(options.max_frames_before_first_scale) {
  options.Check();
}

std::string SequentialPipeline::DiagnosticsCsvHeader() const {
  return backend_ ? MappedFrameCsvHeader() : scale_.DiagnosticsCsvHeader();
}

TrackedFrame SequentialPipeline::Track(const SegmentedFrame& input) {
  const SegmentationResult& segmentation = input.segmentation;
  TrackedFrame tracked = Track(input, [&](const std::vector<Correspondence>&) {
    FrontendMasks masks{segmentation.static_mask, segmentation.dynamic_mask};
    masks.road_mask = segmentation.road_mask;
    return masks;
  });
  FrameRecord& record = tracked.record;
  record.segmentation_ms = segmentation.milliseconds;
  record.segmentation_cpu_ms = input.segmentation_cpu_ms;
  record.segmented = segmentation.fresh && segmentation.HasLabels();
  record.total_ms += segmentation.milliseconds;
  SetRoadMask(segmentation.road_mask, &tracked);
  tracked.dynamic_mask = segmentation.dynamic_mask;
  return tracked;
}

TrackedFrame SequentialPipeline::Track(const SegmentedFrame& input,
                                       const FrontendMaskProvider& masks) {
  const Clock::time_point start = Clock::now();
  const double cpu_start = ThreadCpuMs();
  const Frame& frame = input.frame;
  TrackedFrame tracked;
  FrameRecord& record = tracked.record;
  record.index = frame.index;
  record.timestamp = frame.timestamp;
  record.load_ms = input.load_ms;

  cv::Mat grey = frame.image;
  if (grey.channels() == 3) cv::cvtColor(frame.image, grey, cv::COLOR_BGR2GRAY);
  tracked.frontend = frontend_.ProcessFrame(static_cast<int>(frame.index), grey, masks);
  tracked.image = grey;
  const FrontendFrame& result = tracked.frontend;
  record.motion_status = result.motion.status;
  record.num_tracks = result.num_tracks;
  record.num_correspondences = static_cast<int>(result.correspondences.size());
  record.num_inliers = result.motion.num_inliers;
  record.num_detected = result.tracker.detected;
  record.num_dropped_dynamic = result.tracker.dropped_dynamic;
  record.inlier_ratio = result.motion.inlier_ratio;
  record.flow_px = result.motion.flow_px;
  record.parallax_px = result.motion.parallax_px;
  record.tracking_ms = result.tracker.pyramid_ms + result.tracker.tracking_ms;
  record.detection_ms = result.tracker.detection_ms;
  record.motion_ms = result.motion_ms;
  record.total_ms = MillisecondsSince(start) + input.load_ms;
  record.frontend_cpu_ms = ThreadCpuMs() - cpu_start;
  return tracked;
}

FrameRecord SequentialPipeline::Integrate(TrackedFrame tracked) {
  const Clock::time_point start = Clock::now();
  const double cpu_start = ThreadCpuMs();
  FrameRecord& record = tracked.record;
  const FrontendFrame& result = tracked.frontend;

  if (backend_) {
    records_waiting_for_backend_.push_back(record);
    const Clock::time_point backend_start = Clock::now();
    const std::vector<MappedFrame> finished = backend_->AddFrame(
        result, tracked.road_mask, tracked.image, record.timestamp, tracked.dynamic_mask);
    // The window holds at least two keyframes, so this frame is never among the finished.
    FrameRecord& waiting = records_waiting_for_backend_.back();
    waiting.scale_ms = MillisecondsSince(backend_start);
    waiting.total_ms += MillisecondsSince(start);
    waiting.scale_cpu_ms = ThreadCpuMs() - cpu_start;
    if (provisional_output_) {
      provisional_output_(
          {record.index, record.timestamp, backend_->NewestWorldFromCam(), backend_->scaled()});
    }
    for (const MappedFrame& mapped : finished) OutputMappedFrame(mapped);
    record.status = "waiting";
    return record;
  }

  ScaleResult scale;
  if (result.motion.status != MotionStatus::kFirstFrame) {
    const Clock::time_point scale_start = Clock::now();
    ScaleQuery query;
    query.frame_index = record.index;
    query.position = position_;
    query.frontend = &result;
    query.prev_road_mask = prev_road_mask_;
    scale = scale_.StepLength(query);
    record.scale_ms = MillisecondsSince(scale_start);
  }
  // The scale of the step into the next frame uses this frame's road (Alg. 1 selects the
  // road points in the earlier image of the pair).
  prev_road_mask_ = tracked.road_mask;
  record.scale_valid = scale.valid;
  record.scale_status = scale.status;
  record.scale_diagnostics_csv = scale.diagnostics_csv;
  ++position_;

  if (result.motion.status != MotionStatus::kFirstFrame && !scale.valid &&
      !integrator_.has_scale() && !stopped_waiting_ && max_waiting_frames_ > 0) {
    record.status = "unscaled";
    record.total_ms += MillisecondsSince(start);
    record.scale_cpu_ms = ThreadCpuMs() - cpu_start;
    waiting_.push_back({record, result.motion});
    if (static_cast<int>(waiting_.size()) >= max_waiting_frames_) {
      OutputWaitingFrames(0.0, 0.0);
      stopped_waiting_ = true;
    }
    return record;
  }
  if (!waiting_.empty()) OutputWaitingFrames(scale.step_length_m, result.motion.parallax_px);
  record.total_ms += MillisecondsSince(start);
  record.scale_cpu_ms = ThreadCpuMs() - cpu_start;
  ApplyAndOutput(record, result.motion, scale, false);
  return record;
}

void SequentialPipeline::ApplyAndOutput(FrameRecord record, const TwoViewMotion& motion,
                                        const ScaleResult& scale, bool backfilled) {
  record.pose_update = integrator_.Apply(motion, scale);
  record.step_length_m = integrator_.step_length();
  switch (record.pose_update) {
    case PoseUpdate::kFirst:
      record.status = "first";
      break;
    case PoseUpdate::kKept:
      record.status = "stationary";
      break;
    default:
      record.status = backfilled                 ? "backfilled"
                      : !integrator_.has_scale() ? "unscaled"
                      : scale.measured           ? "ok"
                                                 : "held";
      break;
  }

  if (provisional_output_) {
    provisional_output_(
        {record.index, record.timestamp, integrator_.world_from_cam(), integrator_.has_scale()});
  }
  Output(record, integrator_.world_from_cam());
}

void SequentialPipeline::OutputMappedFrame(const MappedFrame& mapped) {
  if (records_waiting_for_backend_.empty() ||
      records_waiting_for_backend_.front().index != static_cast<size_t>(mapped.frame_index)) {
    throw Error("keyframe back end: frame " + std::to_string(mapped.frame_index) +
                " finished out of order (internal error)");
  }
  FrameRecord record = records_waiting_for_backend_.front();
  records_waiting_for_backend_.pop_front();
  record.keyframe = mapped.keyframe;
  record.bundle_adjustment_ms = mapped.bundle_adjustment.milliseconds;
  record.road_aligned = mapped.alignment_scale > 0.0;
  record.step_length_m =
      (mapped.world_from_cam.translation() - last_written_world_from_cam_.translation()).norm();
  record.scale_valid = mapped.scale != MappedFrame::Scale::kNone;
  record.scale_status = LocalizationName(mapped.localization);
  if (record.motion_status == MotionStatus::kFirstFrame) {
    record.pose_update = PoseUpdate::kFirst;
    record.status = "first";
  } else if (mapped.stationary) {
    record.pose_update = PoseUpdate::kKept;
    record.status = "stationary";
  } else {
    // The frame pair's motion failed (a black frame, every track lost) and the map did not
    // localise the frame: its pose is the prediction, as the frame-to-frame host would say.
    const bool measured = record.motion_status == MotionStatus::kOk ||
                          mapped.localization == MappedFrame::Localization::kMap;
    record.pose_update = measured ? PoseUpdate::kMotion
                         : record.motion_status == MotionStatus::kPureRotation
                             ? PoseUpdate::kRotationOnly
                             : PoseUpdate::kConstantVelocity;
    record.status = mapped.scale == MappedFrame::Scale::kRoad        ? "ok"
                    : mapped.scale == MappedFrame::Scale::kCarried   ? "held"
                    : mapped.scale == MappedFrame::Scale::kPairFixes ? "pair_fixes"
                                                                     : "unscaled";
  }
  record.scale_diagnostics_csv = FormatMappedFrameCsv(mapped);
  last_written_world_from_cam_ = mapped.world_from_cam;
  Output(record, mapped.world_from_cam);
}

void SequentialPipeline::Output(const FrameRecord& record, const Rigid3d& world_from_cam) {
  CheckPoseToOutput(world_from_cam, record);
  if (output_) output_(record, world_from_cam);
}

void SequentialPipeline::OutputWaitingFrames(double first_length_m, double first_parallax_px) {
  std::vector<WaitingFrame> waiting;
  waiting.swap(waiting_);
  for (const WaitingFrame& frame : waiting) {
    ScaleResult scale;
    if (first_length_m > 0.0) {
      scale.valid = true;
      scale.step_length_m =
          ParallaxScaledLength(first_length_m, frame.motion.parallax_px, first_parallax_px);
    }
    ApplyAndOutput(frame.record, frame.motion, scale, first_length_m > 0.0);
  }
}

void SequentialPipeline::Finish() {
  OutputWaitingFrames(0.0, 0.0);
  if (backend_) {
    for (const MappedFrame& mapped : backend_->Finish()) OutputMappedFrame(mapped);
  }
}

void RunSummary::Add(const FrameRecord& record) {
  const double n = static_cast<double>(frames);
  const auto update_mean = [&](double* mean, double value) {
    *mean = (*mean * n + value) / (n + 1);
  };
  update_mean(&mean_load_ms, record.load_ms);
  update_mean(&mean_segmentation_ms, record.segmentation_ms);
  update_mean(&mean_tracking_ms, record.tracking_ms);
  update_mean(&mean_detection_ms, record.detection_ms);
  update_mean(&mean_motion_ms, record.motion_ms);
  update_mean(&mean_scale_ms, record.scale_ms);
  update_mean(&mean_total_ms, record.total_ms);
  update_mean(&mean_segmentation_cpu_ms, record.segmentation_cpu_ms);
  update_mean(&mean_frontend_cpu_ms, record.frontend_cpu_ms);
  update_mean(&mean_scale_cpu_ms, record.scale_cpu_ms);
  if (record.segmented) ++segmented_frames;
  ++frames;
  switch (record.pose_update) {
    case PoseUpdate::kMotion:
      ++motion_frames;
      break;
    case PoseUpdate::kKept:
      ++kept_frames;
      break;
    case PoseUpdate::kRotationOnly:
      ++rotation_only_frames;
      break;
    case PoseUpdate::kConstantVelocity:
      ++constant_velocity_frames;
      break;
    case PoseUpdate::kFirst:
      break;
  }
  if (record.num_detected > 0) ++detection_frames;
  if (record.scale_valid) ++scaled_frames;
  if (record.keyframe) {
    ++keyframes;
    if (record.road_aligned) ++road_aligned_keyframes;
    bundle_adjustment_ms.push_back(record.bundle_adjustment_ms);
  }
}

std::string RunSummary::Format() const {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1);
  out << "Frames: " << frames << " (motion " << motion_frames << ", kept (stationary) "
      << kept_frames << ", rotation only " << rotation_only_frames << ", constant velocity "
      << constant_velocity_frames << "; re-detection in " << detection_frames
      << "; scaled by the scale source in " << scaled_frames << ")\n";
  out << "Mean ms per frame: load " << mean_load_ms << ", segmentation " << mean_segmentation_ms
      << ", tracking " << mean_tracking_ms << ", detection " << mean_detection_ms << ", motion "
      << mean_motion_ms << ", scale " << mean_scale_ms << ", total " << mean_total_ms;
  out << '\n';
  if (frames > 0) {
    out << "Segmented: " << segmented_frames << " of " << frames << " frames ("
        << 100.0 * static_cast<double>(segmented_frames) / static_cast<double>(frames)
        << " %); CPU ms per frame: segmentation " << mean_segmentation_cpu_ms << ", frontend "
        << mean_frontend_cpu_ms << ", scale and pose " << mean_scale_cpu_ms;
    if (cpu_s > 0.0) out << ", whole process " << 1000.0 * cpu_s / static_cast<double>(frames);
    out << '\n';
  }
  if (keyframes > 0) {
    std::vector<double> sorted = bundle_adjustment_ms;
    std::sort(sorted.begin(), sorted.end());
    // Whether the road's pixels fixed the scale: none with bad road masks or a wrong camera.
    out << "Keyframes: " << keyframes << " (the road alignment converged on "
        << road_aligned_keyframes << " of their pairs); bundle adjustment ms per keyframe: median "
        << sorted[sorted.size() / 2] << ", p95 "
        << sorted[std::min(sorted.size() - 1, sorted.size() * 95 / 100)] << '\n';
  }
  if (wall_s > 0.0 && frames > 0) {
    out << "Wall clock: " << std::setprecision(2) << wall_s << " s, " << std::setprecision(1)
        << static_cast<double>(frames) / wall_s << " frames/s end to end\n";
  }
  return out.str();
}

RunSummary RunSequentialPipeline(FrameSource& source, ScaleSource& scale,
                                 const PipelineOptions& options, const std::string& out_dir,
                                 const FrameOutput& on_frame) {
  NoSegmenter no_segmentation;
  RunPipelineOptions run_options;
  run_options.threaded = false;
  return RunPipeline(source, no_segmentation, scale, options, out_dir, run_options, on_frame)
      .summary;
}

}  // namespace roadscale
