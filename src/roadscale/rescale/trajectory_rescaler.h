#pragma once

#include <atomic>
#include <cstddef>
#include <deque>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/frontend/feature_tracker.h"
#include "roadscale/frontend/sampson_refinement.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/rescale/held_step_choice.h"
#include "roadscale/scale/moving_shadows.h"
#include "roadscale/scale/road_plane_alignment.h"
#include "roadscale/scale/scale_estimator.h"
#include "roadscale/scale/scale_filter.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// `roadscale rescale`: the scale module serving another visual odometry (the paper's claim 2).
// Another VO's trajectory (ORB-SLAM3 monocular, DSO, ...) is right up to a scale that is
// unknown and drifts. For each pair of consecutive poses a < b, the rescaler tracks features
// from frame a to frame b (through the frames in between when the VO gives keyframes only),
// takes the VO's relative motion b_from_a (rotation and translation DIRECTION only), and runs
// the road-plane scale estimator of section III on the tracks: h0 / h is the step's length in
// metres. The output keeps every rotation and translation direction of the VO and replaces
// each step's length.
//
// What is filtered is the ratio metres / VO unit of each step, not the step length: a VO's
// scale drifts slowly, while step lengths change with speed and with the (irregular) spacing
// of keyframes. A step without a road plane (flagged "held") keeps the last filtered ratio, so
// that a VO's own scale drift carries the trajectory over road-less stretches, or the car's
// last filtered speed when the road fixes so far show the VO's step lengths less steady than
// the speed (HeldStepChoice).

struct TrajectoryRescalerOptions {
  // Camera height above the road (scale.camera_height, h0) and every threshold of section III.
  // scale.use_filter and scale.filter apply to the ratio described above; the estimator
  // itself runs unfiltered.
  ScaleEstimatorOptions scale;
  // KLT tracking and grid detection as in the frontend, but with FAST corners: here the
  // features serve the road plane, and FAST finds the faint road texture that SIFT's
  // blob detector misses. On a rendered urban street (80 frames) SIFT left 40 % of the
  // steps without a road plane and the path 5 % long; FAST scaled every step, path within
  // 0.3 %; on KITTI 00 the two tie, and FAST costs a tenth (docs/benchmark-history.md).
  FeatureTrackerOptions tracker = [] {
    FeatureTrackerOptions options;
    options.detector.type = DetectorType::kFast;
    return options;
  }();
  // Refine the VO's rotation and direction on this step's tracks (5 degrees of freedom,
  // robust Sampson error) before triangulating. Another program's relative motion is rarely
  // as precise as the images' own geometry: on KITTI the ground truth's direction moves by
  // about 1 degree when refined (../shared/KITTI-NOTES.md), and a 0.035 degree rotation error
  // moves a point at 10 m by 4 % of its depth. The refined motion is only used to triangulate;
  // the output keeps the VO's motion.
  bool refine_motion = true;
  // Measure each step's road plane on the road's pixels as well (road_plane_alignment.h, the
  // keyframe back end's Mapping.road_alignment and its options) when both frames have a road
  // mask: the step's ratio is then the geometric mean of the two planes' ratios, or the one
  // that exists.
  bool road_alignment = true;
  // With the pitch limit at 2 degrees (RoadPlaneAlignmentOptions::max_pitch_to_travel_deg):
  // in KITTI 07's turn the free planes of one-step pairs tilted and came out 30-44 % short
  // (Wang et al.'s input: its length 0.972 of the truth, 0.999 with the limit). The keyframe
  // back end keeps no limit, since a map's direction in a crawl is poorer than a step's own
  // refined one (docs/benchmark-history.md, "Held steps keep the steadier of ratio and speed").
  RoadPlaneAlignmentOptions alignment = [] {
    RoadPlaneAlignmentOptions options;
    options.max_pitch_to_travel_deg = 2.0;
    return options;
  }();
  // Where the alignment finds no plane on the whole road, it tries once more without the
  // moving objects' shadows (the keyframe back end's Mapping.road_alignment_shadow_brightness;
  // 0: no second try).
  double alignment_shadow_brightness = 0.6;
  SampsonRefinementOptions refinement = [] {
    SampsonRefinementOptions options;
    options.loss = SampsonRefinementOptions::Loss::kCauchy;  // the tracks still hold outliers
    return options;
  }();
  // Tracks whose Sampson error under the (refined) motion exceeds this many pixels are left
  // out of the scale estimate and ended: moving objects and drifting tracks.
  double max_sampson_error_px = 1.0;

  // Each step with a road plane of its own takes its own ratio (metres per VO unit), and the
  // filtered ratio (scale.filter) only serves the steps without one (held). The filter
  // assumes a VO whose steps are right up to a slowly drifting scale, and then spreads that
  // VO's step-to-step length errors over the output: real VOs' per-step lengths are not that
  // good (LibVISO2-M's jump by tens of per cent from frame to frame). On the shared KITTI
  // frames the step's own ratio took LibVISO2-M's 00 from 3.45 % to 3.06 % t_err (the floor
  // of its own directions with the true lengths: 3.16 %) and its 07 from a length ratio of
  // 1.036 to 0.990 (floor 0.987), Wang et al.'s 00 from 1.24 % to 1.18 %
  // (docs/benchmark-history.md, "Rescale on two peers' real trajectories"). false: every step the
  // filtered ratio (the previous behaviour, `roadscale rescale --smooth-ratio`).
  bool step_own_ratio = true;
  // A step whose road plane makes the car faster than this (m/s, by its frames' timestamps;
  // 0: no limit) has measured something else: it is held ("held: too fast"). On a rendered
  // highway with every third frame a pose, one step's plane gave 340 times the ratio of the
  // steps before it and the filter carried it over the 48 held steps after. 70 m/s (250
  // km/h), as the keyframe back end's Mapping.first_scale_max_speed.
  double max_speed = 70.0;

  // A step without a road plane of its own is measured again from up to this many poses back
  // (the VO's motion over the span, refined on the tracks through it, and the road alignment
  // between the span's two frames), and takes the span's ratio (metres per VO unit) where the
  // span finds the road; 1: only the step's own pair, as before. The VO's scale drifts slowly,
  // so the span's ratio is the step's too, and a longer baseline and a longer stretch of the
  // VO's path give the road plane what one step may not: a creeping car's step is too short
  // for it, and on KITTI 07 Wang et al.'s single steps in the right turn lay 1-2.5 degrees off
  // the truth's direction, the road alignment tilted 5-12 degrees to fit them and was refused,
  // and 12 steps were held; with spans 3 are (docs/benchmark-history.md, "Held steps measured
  // over a span of poses"). The nearest span that finds the road is taken.
  int max_span_steps = 4;

  // A step whose VO translation is shorter than this fraction of the median (non-zero) step
  // of the whole trajectory is stationary: its metric length stays 0.
  double stationary_fraction = 0.01;

  // Throws Error naming the first invalid option.
  void Check() const;
};

enum class RescaleStatus {
  kFirst,             // the first pose: kept as the VO gives it
  kOk,                // scaled by this step's road plane (or its span's: road_steps)
  kHeld,              // no road plane in this step: the last ratio or speed (see `detail`)
  kBeforeFirstScale,  // before the first road plane: the first ratio, known later
  kStationary,        // the VO did not move: the step stays 0
  kUnscaled,          // no road plane in the whole trajectory: the VO's length kept
};

// "first", "ok", "held", "before first scale", "stationary", "unscaled".
const char* RescaleStatusName(RescaleStatus status);

// One pose of the metric trajectory and the step that led to it (from the previous pose).
struct RescaledPose {
  size_t pose = 0;         // index in the VO's trajectory
  size_t frame = 0;        // frame b of the step (Frame::index)
  size_t prev_frame = 0;   // frame a of the step (== frame for the first pose)
  double timestamp = 0.0;  // frame b's timestamp
  RescaleStatus status = RescaleStatus::kFirst;
  // Why a held step has no road plane ("held: too few points", "held: degenerate"), and
  // ", the speed held" when it keeps the last speed instead of the last ratio.
  std::string detail;
  double duration_s = 0.0;  // from frame a's timestamp to frame b's

  double external_length = 0.0;  // |translation| of the VO's b_from_a, in its units
  // This step's own ratio (metres per VO unit; NaN without a road plane), and the ratio
  // applied (its own, or the filtered one: TrajectoryRescalerOptions::step_own_ratio).
  double raw_ratio = 0.0;
  double ratio = 0.0;
  double metric_length = 0.0;  // ratio * external_length, 0 when stationary

  int num_tracks = 0;    // tracks followed from frame a to frame b
  int num_pairs = 0;     // of those, within max_sampson_error_px: given to the estimator
  bool refined = false;  // the refined motion was used for triangulation
  double refinement_rotation_deg = 0.0;   // how far the refinement moved the VO's motion
  double refinement_direction_deg = 0.0;  // (0 without refinement)
  ScaleEstimate estimate;                 // counts after each stage of the scale estimator
  // The road alignment's ratio (metres per VO unit; NaN when it did not run or converge),
  // and the selected road points' plane's (NaN without one): raw_ratio is their geometric
  // mean, or the one that exists.
  double alignment_ratio = std::numeric_limits<double>::quiet_NaN();
  double points_ratio = std::numeric_limits<double>::quiet_NaN();
  // The steps the road fix spans: 1, the step's own pair; more, measured from that many poses
  // back (TrajectoryRescalerOptions::max_span_steps); 0 without a road fix.
  int road_steps = 0;

  // Milliseconds: segmentation of frame b, KLT over the frames a+1..b, detection in frame
  // b, refinement + scale estimate, and the whole step (frame reading included).
  double segmentation_ms = 0.0;
  double tracking_ms = 0.0;
  double detection_ms = 0.0;
  double scale_ms = 0.0;
  double total_ms = 0.0;

  Rigid3d world_from_cam = Rigid3d::Identity();  // the metric pose of frame b
};

// The frame (position in the source's frames) of each pose of `trajectory`. With timestamps
// (a TUM file): the frame whose timestamp is nearest, within max_difference_s. Without (KITTI
// rows): pose i is frame i. `name` (the trajectory's file) is for the messages. Throws Error
// when a pose matches no frame, when two poses match the same frame or come out of order,
// when there are more poses than frames (KITTI rows), or when there are fewer than 2 poses.
std::vector<size_t> AssociatePosesWithFrames(const Trajectory& trajectory, const std::string& name,
                                             const std::vector<double>& frame_timestamps,
                                             double max_difference_s = 0.01);

// Rescales one trajectory, frame by frame. Frames come in order through AddFrame; finished
// poses come out in order. Poses before the first road plane wait until it is found (they are
// then scaled by its ratio), so output may lag behind input at the start.
class TrajectoryRescaler {
 public:
  // `pose_frames[k]` is the position, among the source's frames, of `external` pose k,
  // strictly increasing (see AssociatePosesWithFrames). options.scale.camera_height is h0.
  // The metric trajectory starts at the VO's first pose. Throws Error on invalid options or
  // camera, or mismatched inputs.
  TrajectoryRescaler(const PinholeCamera& camera, const Trajectory& external,
                     std::vector<size_t> pose_frames, const TrajectoryRescalerOptions& options);

  // The frames the rescaler reads (positions): pose_frames.front() .. pose_frames.back(),
  // every one.
  size_t first_frame() const { return pose_frames_.front(); }
  size_t last_frame() const { return pose_frames_.back(); }
  // Whether the frame at `position` is a pose's frame (segment those frames, and only those).
  bool IsPoseFrame(size_t position) const;
  // The position AddFrame expects next.
  size_t next_frame() const { return next_frame_; }

  // Processes the next frame (positions first_frame(), first_frame() + 1, ...):
  // `frame.image` grey CV_8UC1 of the camera's size; `segmentation` that frame's masks for a pose
  // frame (empty masks = no segmentation; ignored for the frames in between); `segmentation_ms` and
  // `read_ms` for the records. Returns the poses finished by this frame (none, one, or several at
  // once when the first road plane arrives). Throws Error on a bad image.
  std::vector<RescaledPose> AddFrame(const Frame& frame, const SegmentationResult& segmentation,
                                     double segmentation_ms = 0.0, double read_ms = 0.0);

  // After the last frame: the poses still waiting for a first road plane, as kUnscaled (the
  // VO's own lengths). Empty when a road plane was found. Throws Error when frames are missing.
  std::vector<RescaledPose> Finish();
  // The same when the frames stop early (an interruption): the waiting poses as kUnscaled;
  // the steps whose frames were not all read are not emitted.
  std::vector<RescaledPose> FinishEarly();

  // True once a road plane has given a ratio.
  bool has_ratio() const { return has_ratio_; }

 private:
  // A pose's frame, kept for the road fixes of the steps that start at it.
  struct PoseFrame {
    size_t pose = 0;
    size_t position = 0;  // among the source's frames (the tracker's frame index)
    cv::Mat image;        // grey
    cv::Mat road_mask;    // empty: none
    ShadowFreeRoad shadow_free_road;
  };
  // The road fix of the pair from pose frame `from` to pose `to` (the current frame).
  struct PairFix {
    int num_tracks = 0;
    int num_pairs = 0;
    bool refined = false;
    double refinement_rotation_deg = 0.0;
    double refinement_direction_deg = 0.0;
    ScaleEstimate estimate;
    double alignment_ratio = std::numeric_limits<double>::quiet_NaN();
    double points_ratio = std::numeric_limits<double>::quiet_NaN();
    double raw_ratio = std::numeric_limits<double>::quiet_NaN();  // metres per VO unit
    std::vector<int64_t> outliers;  // tracks beyond max_sampson_error_px of the refined motion
  };

  // `current`: the pose's frame (its road mask empty: none; its shadow_free_road: its road less
  // its moving objects' shadows). `seconds`: from the previous pose's frame to this one's
  // (TrajectoryRescalerOptions::max_speed).
  RescaledPose MeasureStep(size_t pose, PoseFrame* current, double seconds);
  PairFix MeasurePair(PoseFrame* from, size_t to, PoseFrame* current);
  // The pair's |t| / h from the road's pixels (NaN when it does not converge).
  double AlignRoad(PoseFrame* from, PoseFrame* current, const Rigid3d& b_from_a,
                   double external_length);
  // Applies `ratio` to the step and chains its pose onto the last emitted one.
  RescaledPose Emit(RescaledPose step);

  PinholeCamera camera_;
  Trajectory external_;
  std::vector<size_t> pose_frames_;
  TrajectoryRescalerOptions options_;
  ScaleEstimator estimator_;
  ScaleFilter ratio_filter_;
  HeldStepChoice held_choice_;
  bool last_step_fixed_ = false;  // the last measured step had its own road plane
  FeatureTracker tracker_;
  double reference_step_length_ = 0.0;  // median non-zero VO step length

  size_t next_frame_ = 0;
  size_t next_pose_ = 0;              // the pose whose frame comes next
  std::deque<PoseFrame> recent_;      // the last max_span_steps poses' frames, newest last
  size_t prev_pose_frame_index_ = 0;  // Frame::index of the last pose's frame
  double prev_pose_timestamp_ = 0.0;  // ... and its timestamp
  bool has_ratio_ = false;
  double ratio_ = 0.0;                // the last filtered ratio
  std::deque<RescaledPose> pending_;  // steps waiting for the first ratio
  Rigid3d last_world_from_cam_ = Rigid3d::Identity();
  // Accumulated over the frames of the current step.
  double step_tracking_ms_ = 0.0;
  double step_total_ms_ = 0.0;
};

// Reads `source`'s frames first_frame() .. last_frame() (the others are not decoded),
// segments the pose frames with `segmenter` (nullptr: no segmentation; the frame's file stem
// is its name), feeds `rescaler`, and calls `on_pose` for each finished pose in order,
// including those Finish() returns. When `stop` becomes true it stops after the frame in
// flight (with FinishEarly()) and returns true; false after the last frame.
bool RunTrajectoryRescaler(const ImageFileSequence& source, Segmenter* segmenter,
                           TrajectoryRescaler& rescaler,
                           const std::function<void(const RescaledPose&)>& on_pose,
                           const std::atomic<bool>* stop = nullptr);

// The header and one row of OUT/rescale.csv (one row per step, i.e. per pose after the
// first).
std::string RescaleCsvHeader();
std::string FormatRescaleCsv(const RescaledPose& pose);

}  // namespace roadscale
