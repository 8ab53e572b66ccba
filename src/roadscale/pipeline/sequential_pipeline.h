#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/mapping/keyframe_backend.h"
#include "roadscale/pipeline/pose_integrator.h"
#include "roadscale/pipeline/scale_source.h"
#include "roadscale/pipeline/segmentation_schedule.h"
#include "roadscale/segmentation/segmentation_result.h"

namespace roadscale {

struct PipelineOptions {
  FrontendOptions frontend;
  // Frames before the first valid scale wait, up to this many, for it: they are then written
  // with the first scale times their parallax over that frame's (ParallaxScaledLength in
  // pose_integrator.h; status "backfilled"). A car often starts from a stop or on a road
  // whose first frames give too few road points; unit steps would stretch the start of the
  // trajectory (on the rendered stop-and-go drive: 14 steps of 1 m for 2.3 m of travel).
  // Past this many frames, and when the run ends without a scale, the waiting frames are
  // written with unit steps ("unscaled"). 0: never wait. 100 frames = 10 s at KITTI's 10 Hz.
  int max_frames_before_first_scale = 100;
  // The host VO: the keyframe back end (mapping/, the default) or the paper's frame-to-frame
  // chaining with the scale source's length per step. The keyframe back end makes its scale
  // itself, from the road selection with `road_selection`'s options (camera_height = h0); the
  // scale source then goes unused. In keyframe mode a frame's rows are written when its
  // keyframe interval leaves the bundle-adjusted window (MappingOptions::window_size).
  MappingOptions mapping;
  ScaleEstimatorOptions road_selection;
  // Which frames a segmenter runs on (RunPipeline; a run without segmentation ignores it).
  SegmentationScheduleOptions segmentation_schedule;

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
  int num_detected = 0;         // new tracks started in this frame
  int num_dropped_dynamic = 0;  // tracks that landed on the dynamic mask
  int road_mask_px = -1;        // road pixels of this frame's mask; -1 without one
  // Live tracks on that mask after detection (-1 without one): the road points a keyframe
  // pair can select from.
  int road_tracks = -1;
  double inlier_ratio = 0.0;
  double flow_px = 0.0;
  double parallax_px = 0.0;
  bool scale_valid = false;
  double step_length_m = 0.0;  // length of the applied step
  std::string scale_status;
  // The frame in one word: "first", "ok" (scaled in this frame), "stationary" (pose kept),
  // "held" (the last valid scale reused: no motion to scale, too few road points, ...),
  // "backfilled" (before the first valid scale: that scale, scaled by the parallax; see
  // PipelineOptions), or "unscaled" (no valid scale at all: the step has unit length, an
  // arbitrary scale).
  std::string status;
  // The scale source's own columns for this frame (ScaleResult::diagnostics_csv).
  std::string scale_diagnostics_csv;

  double load_ms = 0.0;          // decoding the image
  double segmentation_ms = 0.0;  // the segmenter (network or label file; 0 when reused)
  double tracking_ms = 0.0;      // image pyramid + KLT both ways
  double detection_ms = 0.0;     // feature detection (0 when no re-detection)
  double motion_ms = 0.0;        // two-view motion
  double scale_ms = 0.0;
  // The sum of the stages' times (the writing not included). With the threaded runner the stages
  // overlap, so the run's frame rate is not 1000 / total_ms.
  double total_ms = 0.0;

  // Whether the segmenter ran on this frame (its masks are fresh, not reused or carried), and
  // the CPU time of each thread's work on the frame (the segmenter's, the frontend's, and the
  // scale and pose stage's): on a shared machine wall times include the waits for a core.
  bool segmented = false;
  double segmentation_cpu_ms = 0.0;
  double frontend_cpu_ms = 0.0;
  double scale_cpu_ms = 0.0;

  // Keyframe mode: the frame became a keyframe, and the bundle adjustment it started took
  // this long (also counted in scale_ms, the back end's time for the frame).
  bool keyframe = false;
  double bundle_adjustment_ms = 0.0;
  // Keyframe mode: the road alignment of the keyframe's pair converged (frames.csv's
  // alignment_scale is set).
  bool road_aligned = false;
};

// The header and one row of OUT/frames.csv (without the scale source's columns).
std::string FrameRecordCsvHeader();
std::string FormatFrameRecordCsv(const FrameRecord& record);

// One frame as the segmentation stage hands it on: the image and what segmentation knows
// of it (empty masks without segmentation).
struct SegmentedFrame {
  Frame frame;
  SegmentationResult segmentation;
  double load_ms = 0.0;
  double segmentation_cpu_ms = 0.0;
};

// One frame as the frontend stage hands it on.
struct TrackedFrame {
  FrameRecord record;  // the fields up to the frontend's filled in
  FrontendFrame frontend;
  cv::Mat road_mask;     // this frame's road mask, for the next frame's scale query
  cv::Mat image;         // this frame's grey image, for the keyframe back end's road alignment
  cv::Mat dynamic_mask;  // this frame's moving objects (empty: none), for the same
};

// Gives `tracked` its road mask (empty: none) and records its road pixels and the live
// tracks on it.
void SetRoadMask(const cv::Mat& road_mask, TrackedFrame* tracked);

// Where a frame goes once its pose is final, in frame order: its record and its metric
// world_from_cam (the first frame is the world). RunOutputFiles writes them to a run's
// folder; a program embedding the pipeline keeps them in memory.
using FrameOutput = std::function<void(const FrameRecord&, const Rigid3d& world_from_cam)>;

// A frame's pose as soon as the scale and pose stage has taken it: in keyframe mode the map's
// localisation of the frame, which the window's bundle adjustment refines before the frame's
// final pose (FrameOutput) leaves a window later; in frame-to-frame mode the final pose itself.
// For a program that steers by the odometry and cannot wait for the window.
struct ProvisionalPose {
  size_t index = 0;
  double timestamp = 0.0;
  Rigid3d world_from_cam = Rigid3d::Identity();  // the final poses' world
  // Metres once the run has a scale; before it the monocular map's own units.
  bool metric = false;
};
using ProvisionalOutput = std::function<void(const ProvisionalPose&)>;

// The per-frame logic of the system, for each frame: frontend (features outside the static
// mask, tracks landing on moving objects dropped) -> two-view motion -> scale source (with
// the previous frame's road mask) -> pose -> the frame's output. Owns the frontend, the pose
// integrator and the keyframe back end; writes no files (RunOutputFiles does).
//
// The work is split in two stages, Track (the frontend) and Integrate (scale, pose,
// output), which touch disjoint state: one thread may run Track on frame k+1 while another
// runs Integrate on frame k. Each stage must see the frames in order. ProcessFrame runs both.
class SequentialPipeline {
 public:
  // Throws Error on invalid options or camera.
  SequentialPipeline(const CameraSetup& camera, ScaleSource& scale, const PipelineOptions& options);

  // The frontend stage. Throws Error on an image or mask of the wrong size.
  TrackedFrame Track(const SegmentedFrame& frame);
  // The same with the frontend's masks given after KLT (carried from an earlier segmented
  // frame) instead of `frame.segmentation`'s; the caller fills in the road mask and the
  // record's segmentation fields.
  TrackedFrame Track(const SegmentedFrame& frame, const FrontendMaskProvider& masks);

  // The scale and pose stage: hands the frame to the output once its pose is final. Frames
  // before the first valid scale wait (PipelineOptions::max_frames_before_first_scale) and go
  // out with the first scaled frame or with Finish; their returned record says "unscaled". In
  // keyframe mode every frame waits for the back end (frames go out as its window moves on)
  // and the returned record says "waiting". A pose the trajectory readers would reject (not
  // finite, or beyond kMaxTranslationM) never reaches the output: Error names the frame.
  FrameRecord Integrate(TrackedFrame tracked);

  // Receives each finished frame, in frame order (a frame that waits for the first scale
  // later than the call of Integrate that took it). Without one the frames are dropped.
  void SetOutput(FrameOutput output) { output_ = std::move(output); }
  // Receives each frame's provisional pose from Integrate, in frame order; in frame-to-frame
  // mode a frame waiting for the first scale gets it when the frame goes out.
  void SetProvisionalOutput(ProvisionalOutput output) { provisional_output_ = std::move(output); }

  // Hands on the frames still waiting (for a first scale, or in the keyframe back end's
  // window). Call it after the last frame, and after a stop or an error so that the frames
  // already taken are not lost; a second call does nothing.
  void Finish();

  // The columns after FrameRecordCsvHeader() in OUT/frames.csv: the scale source's, or in
  // keyframe mode the back end's (MappedFrameCsvHeader).
  std::string DiagnosticsCsvHeader() const;

 private:
  // A frame's pose from the integrator, handed to the output. `backfilled`: the length is
  // the back-filled one of a frame that waited for the first scale.
  void ApplyAndOutput(FrameRecord record, const TwoViewMotion& motion, const ScaleResult& scale,
                      bool backfilled);
  // Hands on the waiting frames: back-filled from the first scaled step's length and parallax,
  // or without a scale (unit steps) when `first_length_m` is 0.
  void OutputWaitingFrames(double first_length_m, double first_parallax_px);
  // Keyframe mode: the record of a frame the back end has finished, with its pose.
  void OutputMappedFrame(const MappedFrame& mapped);
  // Checks the pose (CheckPoseToOutput) and hands the frame to the output.
  void Output(const FrameRecord& record, const Rigid3d& world_from_cam);

  struct WaitingFrame {
    FrameRecord record;
    TwoViewMotion motion;
  };

  ScaleSource& scale_;
  std::unique_ptr<KeyframeBackend> backend_;  // keyframe mode only
  std::deque<FrameRecord> records_waiting_for_backend_;
  Rigid3d last_written_world_from_cam_ = Rigid3d::Identity();
  MonoFrontend frontend_;
  PoseIntegrator integrator_;
  int max_waiting_frames_ = 0;
  std::vector<WaitingFrame> waiting_;
  FrameOutput output_;
  ProvisionalOutput provisional_output_;
  bool stopped_waiting_ = false;
  size_t position_ = 0;
  cv::Mat prev_road_mask_;
};

// Mean per-stage times and counts over a run.
struct RunSummary {
  size_t frames = 0;
  size_t motion_frames = 0;  // by pose update
  size_t kept_frames = 0;
  size_t rotation_only_frames = 0;
  size_t constant_velocity_frames = 0;
  size_t detection_frames = 0;  // frames with a re-detection
  size_t scaled_frames = 0;     // frames whose step length came from the scale source
  size_t keyframes = 0;
  size_t road_aligned_keyframes = 0;         // whose pair's road alignment converged
  size_t segmented_frames = 0;               // frames the segmenter ran on
  std::vector<double> bundle_adjustment_ms;  // one per keyframe
  double mean_load_ms = 0.0;
  double mean_segmentation_ms = 0.0;
  double mean_tracking_ms = 0.0;
  double mean_detection_ms = 0.0;  // over all frames (detection is not run every frame)
  double mean_motion_ms = 0.0;
  double mean_scale_ms = 0.0;
  double mean_total_ms = 0.0;
  double mean_segmentation_cpu_ms = 0.0;  // over all frames
  double mean_frontend_cpu_ms = 0.0;
  double mean_scale_cpu_ms = 0.0;
  // CPU seconds of the whole process during the run (0 when not measured).
  double cpu_s = 0.0;
  // Wall-clock seconds of the whole run (0 when not measured).
  double wall_s = 0.0;

  void Add(const FrameRecord& record);
  // Several lines for the end of a run.
  std::string Format() const;
};

// Reads every frame of `source` through a SequentialPipeline without segmentation, writing
// its files to `out_dir` (RunOutputFiles); calls `on_frame` after each frame. Returns the
// summary. (RunPipeline in
// run_pipeline.h adds segmentation and threads.)
RunSummary RunSequentialPipeline(FrameSource& source, ScaleSource& scale,
                                 const PipelineOptions& options, const std::string& out_dir,
                                 const FrameOutput& on_frame = {});

}  // namespace roadscale
