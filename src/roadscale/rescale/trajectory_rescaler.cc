#include "roadscale/rescale/trajectory_rescaler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "roadscale/geometry/angles.h"
#include "roadscale/scale/moving_shadows.h"
#include "roadscale/scale/road_model_check.h"
#include "roadscale/util/elapsed_time.h"
#include "roadscale/util/error.h"
#include "roadscale/util/median.h"

#include <Eigen/Geometry>

namespace roadscale {
namespace {

// The VO's motion from pose a to pose b, as cur_from_prev.
Rigid3d PairMotion(const Trajectory& trajectory, size_t a, size_t b) {
  return trajectory.world_from_cam[b].inverse() * trajectory.world_from_cam[a];
}

Rigid3d StepMotion(const Trajectory& trajectory, size_t b) {
  return PairMotion(trajectory, b - 1, b);
}

std::string FormatTime(double seconds) {
  std::ostringstream text;
  text.precision(6);
  text << seconds;
  return text.str();
}

}  // namespace

void TrajectoryRescalerOptions::Check() const {
  scale.Check();
  tracker.Check();
  refinement.Check();
  alignment.Check();
  CheckOption(alignment_shadow_brightness >= 0.0 && alignment_shadow_brightness < 1.0,
              "rescale.alignment_shadow_brightness", "must be in 0..1 (0: off)");
  CheckOption(std::isfinite(max_sampson_error_px) && max_sampson_error_px > 0.0,
              "rescale.max_sampson_error_px", "must be a positive number of pixels");
  CheckOption(
      std::isfinite(stationary_fraction) && stationary_fraction >= 0.0 && stationary_fraction < 1.0,
      "rescale.stationary_fraction", "must be in [0, 1)");
  CheckOption(std::isfinite(max_speed) && max_speed >= 0.0, "rescale.max_speed",
              "must be >= 0 m/s (0: no limit)");
  CheckOption(max_span_steps >= 1, "rescale.max_span_steps",
              "must be >= 1 (1: each step's own pair only)");
}

const char* RescaleStatusName(RescaleStatus status) {
  switch (status) {
    case RescaleStatus::kFirst:
      return "first";
    case RescaleStatus::kOk:
      return "ok";
    case RescaleStatus::kHeld:
      return "held";
    case RescaleStatus::kBeforeFirstScale:
      return "before first scale";
    case RescaleStatus::kStationary:
      return "stationary";
    case RescaleStatus::kUnscaled:
      return "unscaled";
  }
  return "unknown";
}

std::vector<size_t> AssociatePosesWithFrames(const Trajectory& trajectory, const std::string& name,
                                             const std::vector<double>& frame_timestamps,
                                             double max_difference_s) {
  if (trajectory.size() < 2) {
    ThrowFileError(name, "has " + std::to_string(trajectory.size()) +
                             " pose(s); rescaling needs at least 2 (one step)");
  }
  std::vector<size_t> frames;
  frames.reserve(trajectory.size());
  if (!trajectory.HasTimestamps()) {
    if (trajectory.size() > frame_timestamps.size()) {
      ThrowFileError(name, "has " + std::to_string(trajectory.size()) +
                               " poses but there are only " +
                               std::to_string(frame_timestamps.size()) +
                               " frames; KITTI rows are frames 0, 1, 2, ... (for keyframes "
                               "only, give a TUM file with timestamps)");
    }
    for (size_t k = 0; k < trajectory.size(); ++k) frames.push_back(k);
    return frames;
  }
  if (!std::isfinite(max_difference_s) || max_difference_s < 0.0) {
    throw Error("invalid option max_time_diff: must be a non-negative number of seconds");
  }
  if (frame_timestamps.empty()) ThrowFileError(name, "there are no frames to associate with");
  for (size_t k = 0; k < trajectory.size(); ++k) {
    const double t = trajectory.timestamps[k];
    // The nearest frame: the first at or after t, or the one before it (on a tie too).
    size_t best =
        static_cast<size_t>(std::lower_bound(frame_timestamps.begin(), frame_timestamps.end(), t) -
                            frame_timestamps.begin());
    if (best == frame_timestamps.size() ||
        (best > 0 && t - frame_timestamps[best - 1] <= frame_timestamps[best] - t)) {
      best = best > 0 ? best - 1 : 0;
    }
    const double difference = std::abs(frame_timestamps[best] - t);
    if (!(difference <= max_difference_s)) {
      ThrowFileError(name, "pose " + std::to_string(k) + " (timestamp " + FormatTime(t) +
                               " s) matches no frame: the nearest frame, " + std::to_string(best) +
                               ", is at " + FormatTime(frame_timestamps[best]) + " s (more than " +
                               FormatTime(max_difference_s) + " s away; frames span " +
                               FormatTime(frame_timestamps.front()) + " to " +
                               FormatTime(frame_timestamps.back()) + " s)");
    }
    if (!frames.empty() && best <= frames.back()) {
      ThrowFileError(name, "poses " + std::to_string(k - 1) + " and " + std::to_string(k) +
                               " (timestamps " + FormatTime(trajectory.timestamps[k - 1]) +
                               " and " + FormatTime(t) + " s) match frames " +
                               std::to_string(frames.back()) + " and " + std::to_string(best) +
                               "; expected one pose per frame, in increasing time");
    }
    frames.push_back(best);
  }
  return frames;
}

TrajectoryRescaler::TrajectoryRescaler(const PinholeCamera& camera, const Trajectory& external,
                                       std::vector<size_t> pose_frames,
                                       const TrajectoryRescalerOptions& options)
    : camera_(camera),
      external_(external),
      pose_frames_(std::move(pose_frames)),
      options_(options),
      estimator_(camera,
                 [&options] {
                   ScaleEstimatorOptions scale = options.scale;
                   scale.use_filter = false;  // the ratio is filtered here instead
                   return scale;
                 }()),
      ratio_filter_(options.scale.filter),
      held_choice_(options.scale.filter),
      tracker_(options.tracker) {
  options_.Check();
  if (external_.size() < 2) {
    throw Error("rescaling needs a trajectory of at least 2 poses, got " +
                std::to_string(external_.size()));
  }
  if (pose_frames_.size() != external_.size()) {
    throw Error("rescaling: " + std::to_string(external_.size()) + " poses but " +
                std::to_string(pose_frames_.size()) + " pose frames");
  }
  for (size_t k = 1; k < pose_frames_.size(); ++k) {
    if (pose_frames_[k] <= pose_frames_[k - 1]) {
      throw Error("rescaling: the frames of poses " + std::to_string(k - 1) + " and " +
                  std::to_string(k) + " are not increasing");
    }
  }
  std::vector<double> lengths;
  for (size_t b = 1; b < external_.size(); ++b) {
    const double length = StepMotion(external_, b).translation().norm();
    if (!std::isfinite(length)) {
      throw Error("rescaling: pose " + std::to_string(b) + " of the trajectory is not finite");
    }
    if (length > 0.0) lengths.push_back(length);
  }
  reference_step_length_ = Median(lengths);
  next_frame_ = pose_frames_.front();
  last_world_from_cam_ = external_.world_from_cam.front();
}

bool TrajectoryRescaler::IsPoseFrame(size_t position) const {
  return std::binary_search(pose_frames_.begin(), pose_frames_.end(), position);
}

std::vector<RescaledPose> TrajectoryRescaler::AddFrame(const Frame& frame,
                                                       const SegmentationResult& segmentation,
                                                       double segmentation_ms, double read_ms) {
  if (next_pose_ >= pose_frames_.size()) {
    throw Error("rescaling: frame " + std::to_string(frame.index) +
                " comes after the trajectory's last pose");
  }
  if (frame.image.type() != CV_8UC1 || frame.image.cols != camera_.width ||
      frame.image.rows != camera_.height) {
    throw Error("rescaling: frame " + std::to_string(frame.index) + " is " +
                std::to_string(frame.image.cols) + "x" + std::to_string(frame.image.rows) +
                (frame.image.type() == CV_8UC1 ? "" : " and not 8-bit grey") + ", the camera's " +
                std::to_string(camera_.width) + "x" + std::to_string(camera_.height));
  }
  const auto start = std::chrono::steady_clock::now();
  const size_t position = next_frame_;
  const bool pose_frame = position == pose_frames_[next_pose_];
  const cv::Mat no_mask;
  std::vector<RescaledPose> finished;

  if (next_pose_ == 0) {
    tracker_.Track(static_cast<int>(position), frame.image, segmentation.dynamic_mask);
    tracker_.Detect(segmentation.static_mask, /*force=*/true);
    PoseFrame first_frame;
    first_frame.pose = 0;
    first_frame.position = position;
    first_frame.image = frame.image;
    first_frame.road_mask = segmentation.road_mask.clone();
    first_frame.shadow_free_road =
        ShadowFreeRoad(first_frame.image, first_frame.road_mask, segmentation.dynamic_mask.clone());
    recent_.push_back(std::move(first_frame));
    prev_pose_frame_index_ = frame.index;
    prev_pose_timestamp_ = frame.timestamp;
    RescaledPose first;
    first.frame = first.prev_frame = frame.index;
    first.timestamp = frame.timestamp;
    first.world_from_cam = last_world_from_cam_;
    first.segmentation_ms = segmentation_ms;
    first.total_ms = segmentation_ms + read_ms + MillisecondsSince(start);
    finished.push_back(first);
    ++next_pose_;
    ++next_frame_;
    return finished;
  }

  // KLT starts in each frame where the VO's rotation of this step, spread evenly over its
  // frames, moves each point.
  const Eigen::AngleAxisd step_rotation(
      NearestRotation(StepMotion(external_, next_pose_).linear()));
  const double frames =
      static_cast<double>(pose_frames_[next_pose_] - pose_frames_[next_pose_ - 1]);
  const Eigen::Matrix3d per_frame =
      Eigen::AngleAxisd(step_rotation.angle() / frames, step_rotation.axis()).toRotationMatrix();
  const Eigen::Matrix3d prediction = camera_.K() * per_frame * camera_.K().inverse();
  tracker_.Track(static_cast<int>(position), frame.image,
                 pose_frame ? segmentation.dynamic_mask : no_mask, prediction);
  step_tracking_ms_ += tracker_.stats().pyramid_ms + tracker_.stats().tracking_ms;
  ++next_frame_;
  if (!pose_frame) {
    step_total_ms_ += read_ms + MillisecondsSince(start);
    return finished;
  }

  PoseFrame current;
  current.pose = next_pose_;
  current.position = position;
  current.image = frame.image;
  current.road_mask = segmentation.road_mask.clone();
  current.shadow_free_road =
      ShadowFreeRoad(current.image, current.road_mask, segmentation.dynamic_mask.clone());
  RescaledPose step = MeasureStep(next_pose_, &current, frame.timestamp - prev_pose_timestamp_);
  step.frame = frame.index;
  step.prev_frame = prev_pose_frame_index_;
  prev_pose_frame_index_ = frame.index;
  prev_pose_timestamp_ = frame.timestamp;
  step.timestamp = frame.timestamp;
  step.segmentation_ms = segmentation_ms;
  step.tracking_ms = step_tracking_ms_;
  // New features (topping up the grid cells) at every pose, not only when the tracks run low:
  // the road right in front of the car leaves the image within a few frames, and the scale
  // needs its points in every step.
  constexpr bool kDetectEveryPose = true;
  tracker_.Detect(segmentation.static_mask, kDetectEveryPose);
  step.detection_ms = tracker_.stats().detection_ms;
  recent_.push_back(std::move(current));
  while (recent_.size() > static_cast<size_t>(options_.max_span_steps)) recent_.pop_front();
  step.total_ms = step_total_ms_ + segmentation_ms + read_ms + MillisecondsSince(start);
  step_tracking_ms_ = 0.0;
  step_total_ms_ = 0.0;
  ++next_pose_;

  if (!has_ratio_) {
    pending_.push_back(std::move(step));
    return finished;  // nothing to scale with yet
  }
  if (!pending_.empty()) {
    // The first road plane: the steps before it take its ratio.
    while (!pending_.empty()) {
      RescaledPose waiting = std::move(pending_.front());
      pending_.pop_front();
      if (waiting.status != RescaleStatus::kStationary) {
        waiting.status = RescaleStatus::kBeforeFirstScale;
      }
      finished.push_back(Emit(std::move(waiting)));
    }
  }
  finished.push_back(Emit(std::move(step)));
  return finished;
}

double TrajectoryRescaler::AlignRoad(PoseFrame* from, PoseFrame* current, const Rigid3d& b_from_a,
                                     double external_length) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (!options_.road_alignment || current->road_mask.empty() || from->road_mask.empty() ||
      current->image.channels() != 1) {
    return none;
  }
  // The last ratio predicts this pair's |t| / h; before the first, the whole range is searched.
  const double expected =
      has_ratio_ ? ratio_ * external_length / options_.scale.camera_height : 0.0;
  const std::optional<Eigen::Vector3d> normal =
      ExpectedRoadNormal(b_from_a, options_.scale.road_model);
  const Eigen::Vector3d normal_guess = normal.value_or(Eigen::Vector3d::UnitY());
  RoadPlaneAlignment alignment =
      AlignRoadPlane(from->image, current->image, from->road_mask, current->road_mask, camera_,
                     b_from_a, normal_guess, expected, options_.alignment);
  const double brightness = options_.alignment_shadow_brightness;
  if (!alignment.ok && brightness > 0.0) {
    // The whole road found no plane: once more without the moving objects' shadows.
    if (from->shadow_free_road.HasShadows(brightness) ||
        current->shadow_free_road.HasShadows(brightness)) {
      alignment =
          AlignRoadPlane(from->image, current->image, from->shadow_free_road.Road(brightness),
                         current->shadow_free_road.Road(brightness), camera_, b_from_a,
                         normal_guess, expected, options_.alignment);
    }
  }
  if (!alignment.ok) return none;
  return options_.scale.camera_height / (alignment.plane.height * external_length);
}

TrajectoryRescaler::PairFix TrajectoryRescaler::MeasurePair(PoseFrame* from, size_t to,
                                                            PoseFrame* current) {
  PairFix fix;
  const Rigid3d b_from_a = PairMotion(external_, from->pose, to);
  const double external_length = b_from_a.translation().norm();
  // A span over which the VO went nowhere (it stood still, or came back): no direction.
  if (!(external_length > options_.stationary_fraction * reference_step_length_)) return fix;

  std::vector<int64_t> ids;
  std::vector<Eigen::Vector2d> prev_pixels;
  std::vector<Eigen::Vector2d> cur_pixels;
  for (const Track& track : tracker_.tracks()) {
    if (track.first_frame > static_cast<int>(from->position)) continue;
    ids.push_back(track.id);
    prev_pixels.push_back(track.pixels[from->position - static_cast<size_t>(track.first_frame)]);
    cur_pixels.push_back(track.pixels.back());
  }
  fix.num_tracks = static_cast<int>(ids.size());

  Eigen::Matrix3d rotation = NearestRotation(b_from_a.linear());
  Eigen::Vector3d direction = b_from_a.translation() / external_length;
  std::vector<Eigen::Vector2d> prev_normalized;
  std::vector<Eigen::Vector2d> cur_normalized;
  prev_normalized.reserve(ids.size());
  cur_normalized.reserve(ids.size());
  for (size_t i = 0; i < ids.size(); ++i) {
    prev_normalized.push_back(camera_.Unproject(prev_pixels[i]).head<2>());
    cur_normalized.push_back(camera_.Unproject(cur_pixels[i]).head<2>());
  }
  // Five unknowns: fewer tracks than a handful fit anything.
  constexpr size_t kMinRefinementTracks = 20;
  // A refinement that turns the rotation or the direction further than this from the VO's is
  // not used (a false minimum, or too few good tracks): the VO's motion is.
  constexpr double kMaxRefinementRotationDeg = 1.0;
  constexpr double kMaxRefinementDirectionDeg = 5.0;
  if (options_.refine_motion && ids.size() >= kMinRefinementTracks) {
    const SampsonRefinementResult refined = RefineRelativePoseSampson(
        rotation, direction, prev_normalized, cur_normalized, camera_.fx, options_.refinement);
    fix.refinement_rotation_deg =
        RotationAngle(refined.rotation * rotation.transpose()) * kDegreesPerRadian;
    fix.refinement_direction_deg =
        std::acos(std::clamp(refined.direction.normalized().dot(direction), -1.0, 1.0)) *
        kDegreesPerRadian;
    if (fix.refinement_rotation_deg <= kMaxRefinementRotationDeg &&
        fix.refinement_direction_deg <= kMaxRefinementDirectionDeg) {
      rotation = refined.rotation;
      direction = refined.direction.normalized();
      fix.refined = true;
    }
  }

  const Eigen::Matrix3d essential = SkewMatrix(direction) * rotation;
  std::vector<Eigen::Vector2d> kept_prev;
  std::vector<Eigen::Vector2d> kept_cur;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (std::abs(SampsonErrorPx(essential, prev_normalized[i], cur_normalized[i], camera_.fx)) <=
        options_.max_sampson_error_px) {
      kept_prev.push_back(prev_pixels[i]);
      kept_cur.push_back(cur_pixels[i]);
    } else {
      fix.outliers.push_back(ids[i]);
    }
  }
  fix.num_pairs = static_cast<int>(kept_prev.size());

  fix.estimate =
      estimator_.Estimate(kept_prev, kept_cur, MakeRigid3d(rotation, direction), from->road_mask);
  fix.alignment_ratio = AlignRoad(from, current, MakeRigid3d(rotation, direction), external_length);
  if (fix.estimate.status == ScaleStatus::kOk) {
    fix.points_ratio = fix.estimate.raw_scale / external_length;
  }
  // Two measurements of the same plane with errors of their own: their geometric mean beat
  // either alone on KITTI 00 and was between them on the rendered street
  // (docs/benchmark-history.md, "Rescale").
  if (std::isfinite(fix.alignment_ratio) && std::isfinite(fix.points_ratio)) {
    fix.raw_ratio = std::sqrt(fix.alignment_ratio * fix.points_ratio);
  } else if (std::isfinite(fix.alignment_ratio) || std::isfinite(fix.points_ratio)) {
    fix.raw_ratio = std::isfinite(fix.alignment_ratio) ? fix.alignment_ratio : fix.points_ratio;
  }
  return fix;
}

RescaledPose TrajectoryRescaler::MeasureStep(size_t pose, PoseFrame* current, double seconds) {
  const auto start = std::chrono::steady_clock::now();
  RescaledPose step;
  step.pose = pose;
  step.duration_s = seconds;
  step.external_length = StepMotion(external_, pose).translation().norm();
  step.raw_ratio = std::numeric_limits<double>::quiet_NaN();
  if (!(step.external_length > options_.stationary_fraction * reference_step_length_)) {
    last_step_fixed_ = false;
    step.status = RescaleStatus::kStationary;
    step.num_tracks = static_cast<int>(
        std::count_if(tracker_.tracks().begin(), tracker_.tracks().end(), [&](const Track& track) {
          return track.first_frame <= static_cast<int>(recent_.back().position);
        }));
    step.scale_ms = MillisecondsSince(start);
    return step;
  }

  const PairFix own = MeasurePair(&recent_.back(), pose, current);
  step.num_tracks = own.num_tracks;
  step.num_pairs = own.num_pairs;
  step.refined = own.refined;
  step.refinement_rotation_deg = own.refinement_rotation_deg;
  step.refinement_direction_deg = own.refinement_direction_deg;
  step.estimate = own.estimate;
  step.alignment_ratio = own.alignment_ratio;
  step.points_ratio = own.points_ratio;
  step.raw_ratio = own.raw_ratio;
  if (std::isfinite(step.raw_ratio)) step.road_steps = 1;
  // Only a motion the tracks agree with may end tracks: with the VO's unrefined motion a
  // few tenths of a degree off, good tracks far from the epipole would go too.
  if (own.refined) tracker_.Drop(own.outliers);
  // No road plane of its own: the nearest span back that has one.
  for (size_t back = 2; !std::isfinite(step.raw_ratio) && back <= recent_.size(); ++back) {
    const PairFix span = MeasurePair(&recent_[recent_.size() - back], pose, current);
    if (std::isfinite(span.raw_ratio)) {
      step.raw_ratio = span.raw_ratio;
      step.road_steps = static_cast<int>(back);
      step.detail = "over the last " + std::to_string(back) + " steps";
    }
  }

  const bool too_fast = std::isfinite(step.raw_ratio) && options_.max_speed > 0.0 &&
                        seconds > 0.0 &&
                        step.raw_ratio * step.external_length / seconds > options_.max_speed;
  if (too_fast) {
    step.raw_ratio = std::numeric_limits<double>::quiet_NaN();
    step.road_steps = 0;
    step.status = RescaleStatus::kHeld;
    step.detail = "held: too fast";
  } else if (std::isfinite(step.raw_ratio)) {
    ratio_ = options_.scale.use_filter ? ratio_filter_.Add(step.raw_ratio) : step.raw_ratio;
    has_ratio_ = true;
    step.status = RescaleStatus::kOk;
    if (step.road_steps == 1) {
      const double speed = seconds > 0.0 ? step.raw_ratio * step.external_length / seconds : 0.0;
      held_choice_.AddFixed(step.raw_ratio, speed, last_step_fixed_);
    }
  } else {
    step.status = RescaleStatus::kHeld;
    step.detail = ScaleStatusName(step.estimate.status);
  }
  // HeldStepChoice compares consecutive steps' own fixes; a span's is not one.
  last_step_fixed_ = step.status == RescaleStatus::kOk && step.road_steps == 1;
  step.scale_ms = MillisecondsSince(start);
  return step;
}

RescaledPose TrajectoryRescaler::Emit(RescaledPose step) {
  const Rigid3d b_from_a = StepMotion(external_, step.pose);
  const bool own_ratio =
      options_.step_own_ratio && step.status == RescaleStatus::kOk && std::isfinite(step.raw_ratio);
  step.ratio = step.status == RescaleStatus::kUnscaled ? 1.0 : own_ratio ? step.raw_ratio : ratio_;
  if (step.status == RescaleStatus::kHeld && held_choice_.HoldsSpeed() && step.duration_s > 0.0 &&
      step.external_length > 0.0 && std::isfinite(held_choice_.speed())) {
    step.ratio = held_choice_.speed() * step.duration_s / step.external_length;
    step.detail += ", the speed held";
  }

  step.metric_length =
      step.status == RescaleStatus::kStationary ? 0.0 : step.ratio * step.external_length;
  const Eigen::Vector3d translation =
      step.external_length > 0.0
          ? Eigen::Vector3d(b_from_a.translation() / step.external_length * step.metric_length)
          : Eigen::Vector3d::Zero();
  const Rigid3d metric_b_from_a = MakeRigid3d(NearestRotation(b_from_a.linear()), translation);
  last_world_from_cam_ = last_world_from_cam_ * metric_b_from_a.inverse();
  step.world_from_cam = last_world_from_cam_;
  return step;
}

std::vector<RescaledPose> TrajectoryRescaler::Finish() {
  if (next_pose_ < pose_frames_.size()) {
    throw Error("rescaling: the frames ended at position " + std::to_string(next_frame_) +
                ", before the frame of the trajectory's last pose (" +
                std::to_string(pose_frames_.back()) + ")");
  }
  return FinishEarly();
}

std::vector<RescaledPose> TrajectoryRescaler::FinishEarly() {
  std::vector<RescaledPose> finished;
  while (!pending_.empty()) {
    RescaledPose waiting = std::move(pending_.front());
    pending_.pop_front();
    if (waiting.status != RescaleStatus::kStationary) waiting.status = RescaleStatus::kUnscaled;
    finished.push_back(Emit(std::move(waiting)));
  }
  return finished;
}

bool RunTrajectoryRescaler(const ImageFileSequence& source, Segmenter* segmenter,
                           TrajectoryRescaler& rescaler,
                           const std::function<void(const RescaledPose&)>& on_pose,
                           const std::atomic<bool>* stop) {
  if (rescaler.last_frame() >= source.size()) {
    throw Error("rescaling: the trajectory's last pose is at frame position " +
                std::to_string(rescaler.last_frame()) + " but the input has " +
                std::to_string(source.size()) + " frames");
  }
  const SegmentationResult no_segmentation;
  for (size_t position = rescaler.first_frame(); position <= rescaler.last_frame(); ++position) {
    if (stop != nullptr && stop->load()) {
      for (const RescaledPose& pose : rescaler.FinishEarly()) on_pose(pose);
      return true;
    }
    const auto start = std::chrono::steady_clock::now();
    const Frame frame = source.Read(position);
    const double read_ms = MillisecondsSince(start);
    SegmentationResult segmentation;
    double segmentation_ms = 0.0;
    if (segmenter != nullptr && rescaler.IsPoseFrame(position)) {
      const auto segmentation_start = std::chrono::steady_clock::now();
      segmentation =
          segmenter->Segment(frame.image, std::filesystem::path(frame.path).stem().string());
      segmentation_ms = MillisecondsSince(segmentation_start);
    }
    for (const RescaledPose& pose :
         rescaler.AddFrame(frame, segmenter != nullptr ? segmentation : no_segmentation,
                           segmentation_ms, read_ms)) {
      on_pose(pose);
    }
  }
  for (const RescaledPose& pose : rescaler.Finish()) on_pose(pose);
  return false;
}

std::string RescaleCsvHeader() {
  return "pose,frame_a,frame_b,timestamp,status,detail,external_length,raw_ratio,ratio,"
         "metric_length,tracks,pairs,refined,refinement_rotation_deg,refinement_direction_deg,"
         "triangulated,preselected,after_vote,after_road_model,ransac_inliers,plane_h,"
         "alignment_ratio,points_ratio,road_steps,segmentation_ms,tracking_ms,detection_ms,scale_"
         "ms,total_ms";
}

std::string FormatRescaleCsv(const RescaledPose& pose) {
  std::ostringstream row;
  row.precision(9);
  const ScaleEstimate& e = pose.estimate;
  row << pose.pose << ',' << pose.prev_frame << ',' << pose.frame << ',' << pose.timestamp << ",\""
      << RescaleStatusName(pose.status) << "\",\"" << pose.detail << "\"," << pose.external_length
      << ',' << pose.raw_ratio << ',' << pose.ratio << ',' << pose.metric_length << ','
      << pose.num_tracks << ',' << pose.num_pairs << ',' << (pose.refined ? 1 : 0) << ','
      << pose.refinement_rotation_deg << ',' << pose.refinement_direction_deg << ','
      << e.num_triangulated << ',' << e.num_preselected << ',' << e.num_after_vote << ','
      << e.num_after_road_model << ',' << e.num_ransac_inliers << ',';
  if (e.status == ScaleStatus::kOk) row << e.plane.height;
  row << ',';
  if (std::isfinite(pose.alignment_ratio)) row << pose.alignment_ratio;
  row << ',';
  if (std::isfinite(pose.points_ratio)) row << pose.points_ratio;
  row << ',' << pose.road_steps;
  row.precision(4);
  row << ',' << pose.segmentation_ms << ',' << pose.tracking_ms << ',' << pose.detection_ms << ','
      << pose.scale_ms << ',' << pose.total_ms;
  return row.str();
}

}  // namespace roadscale
