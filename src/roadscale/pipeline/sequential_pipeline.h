#pragma once

#include <cstddef>
#include <fstream>
#include <functional>
#include <string>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/pipeline/pose_integrator.h"
#include "roadscale/pipeline/scale_source.h"

namespace roadscale {

struct PipelineOptions {
  FrontendOptions frontend;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// What happened in one frame, with the time each stage took (milliseconds, wall clock).
struct FrameRecord {
  size_t index = 0;  // frame index in the whole input
  double timestamp = 0.0;
  MotionStatus motion_status = MotionStatus::kFirstFrame;
  PoseUpdate pose_update = PoseUpdate::kFirst;
  int num_tracks = 0;           // live tracks after this frame
  int num_correspondences = 0;  // tracks seen in the previous and this frame
  int num_inliers = 0;
  int num_detected = 0;  // new tracks started in this frame
  double inlier_ratio = 0.0;
  double flow_px = 0.0;
  double parallax_px = 0.0;
  bool scale_valid = false;
  double step_length_m = 0.0;  // length of the applied step
  std::string scale_status;

  double load_ms = 0.0;       // decoding the image
  double tracking_ms = 0.0;   // image pyramid + KLT both ways
  double detection_ms = 0.0;  // feature detection (0 when no re-detection)
  double motion_ms = 0.0;     // two-view motion
  double scale_ms = 0.0;
  double total_ms = 0.0;  // the whole frame, writing included
};

// The header and one row of OUT/frames.csv.
std::string FrameRecordCsvHeader();
std::string FormatFrameRecordCsv(const FrameRecord& record);

// The first, sequential system: for each frame, frontend -> two-view motion -> scale source ->
// pose. Owns the frontend, the pose integrator and the output files.
class SequentialPipeline {
 public:
  // Creates `out_dir` when needed and opens OUT/poses_kitti.txt and OUT/frames.csv. Throws
  // Error on invalid options or camera, or when the files cannot be created.
  SequentialPipeline(const CameraSetup& camera, ScaleSource& scale, const PipelineOptions& options,
                     const std::string& out_dir);

  // Processes the next frame and appends its pose row and record, flushed, so that a run
  // stopped at frame k leaves the rows of frames before k intact. Frames must come in order.
  // `load_ms`: how long decoding the frame took, for the record.
  FrameRecord ProcessFrame(const Frame& frame, double load_ms = 0.0);

  const Rigid3d& world_from_cam() const { return integrator_.world_from_cam(); }
  const std::string& poses_path() const { return poses_path_; }
  const std::string& records_path() const { return records_path_; }

 private:
  ScaleSource& scale_;
  MonoFrontend frontend_;
  PoseIntegrator integrator_;
  size_t position_ = 0;
  std::string poses_path_;
  std::string records_path_;
  std::ofstream poses_;
  std::ofstream records_;
};

// Mean per-stage times and counts over a run.
struct RunSummary {
  size_t frames = 0;
  size_t motion_frames = 0;  // by pose update
  size_t kept_frames = 0;
  size_t rotation_only_frames = 0;
  size_t constant_velocity_frames = 0;
  size_t detection_frames = 0;  // frames with a re-detection
  double mean_load_ms = 0.0;
  double mean_tracking_ms = 0.0;
  double mean_detection_ms = 0.0;  // over all frames (detection is not run every frame)
  double mean_motion_ms = 0.0;
  double mean_scale_ms = 0.0;
  double mean_total_ms = 0.0;

  void Add(const FrameRecord& record);
  // Several lines for the end of a run.
  std::string Format() const;
};

// Reads every frame of `source` through a SequentialPipeline writing to `out_dir`; calls
// `on_frame` after each frame. Returns the summary.
RunSummary RunSequentialPipeline(FrameSource& source, ScaleSource& scale,
                                 const PipelineOptions& options, const std::string& out_dir,
                                 const std::function<void(const FrameRecord&)>& on_frame = {});

}  // namespace roadscale
