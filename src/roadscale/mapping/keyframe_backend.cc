#include "roadscale/mapping/keyframe_backend.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>

#include "roadscale/frontend/two_view_motion.h"
#include "roadscale/mapping/road_height_gate.h"
#include "roadscale/scale/moving_shadows.h"
#include "roadscale/scale/road_model_check.h"
#include "roadscale/scale/road_plane_ransac.h"
#include "roadscale/util/error.h"
#include "roadscale/util/median.h"

namespace roadscale {
namespace {

Eigen::Vector3d Centre(const Rigid3d& cam_from_world) {
  return cam_from_world.inverse().translation();
}

Keyframe MakeKeyframe(const FrontendFrame& frontend, const cv::Mat& road_mask, const cv::Mat& image,
                      const cv::Mat& dynamic_mask, double timestamp,
                      const Rigid3d& cam_from_world) {
  Keyframe keyframe;
  keyframe.frame_index = frontend.frame_index;
  keyframe.timestamp = timestamp;
  keyframe.cam_from_world = cam_from_world;
  for (const TrackObservation& o : frontend.observations) {
    keyframe.observations[o.track_id] = o.pixel;
  }
  keyframe.road_mask = road_mask;
  keyframe.image = image;
  keyframe.shadow_free_road = ShadowFreeRoad(image, road_mask, dynamic_mask);
  return keyframe;
}

int CountSharedTracks(const Keyframe& a, const Keyframe& b) {
  int shared = 0;
  for (const auto& observation : b.observations) shared += a.observations.count(observation.first);
  return shared;
}

ScaleEstimatorOptions SelectionOptions(ScaleEstimatorOptions options, double camera_height,
                                       int min_points) {
  options.camera_height = camera_height;
  options.ransac.min_points = std::max(min_points, 3);
  // The selection's plane only chooses road points and gives their normal; the window's
  // adjustment makes the scale, so the per-pair filter has nothing to do.
  options.use_filter = false;
  return options;
}

}  // namespace

void MappingOptions::Check() const {
  CheckOption(window_size >= 2, "mapping.window_size", "must be >= 2 keyframes");
  CheckOption(road_min_points_per_pair >= 3, "mapping.road_min_points_per_pair",
              "must be >= 3 (a plane needs three points)");
  CheckOption(road_pool_pairs >= 1, "mapping.road_pool_pairs", "must be >= 1 (1: no pooling)");
  CheckOption(road_max_height_ratio > 1.0 && std::isfinite(road_max_height_ratio),
              "mapping.road_max_height_ratio", "must be a number > 1");
  CheckOption(road_alignment_shadow_brightness >= 0.0 && road_alignment_shadow_brightness < 1.0,
              "mapping.road_alignment_shadow_brightness", "must be in 0..1 (0: off)");
  CheckOption(std::isfinite(first_scale_max_speed) && first_scale_max_speed >= 0.0,
              "mapping.first_scale_max_speed", "must be >= 0 m/s (0: no limit)");
  keyframes.Check();
  landmarks.Check();
  localization.Check();
  bundle_adjustment.Check();
  alignment.Check();
  CheckOption(std::isfinite(road_region_max_distance) && road_region_max_distance >= 0.0,
              "mapping.road_alignment_region_distance", "must be >= 0 camera heights (0: off)");
  CheckOption(std::isfinite(road_region_half_width) && road_region_half_width > 0.0,
              "mapping.road_alignment_region_half_width", "must be > 0 camera heights");
}

std::string MappedFrameCsvHeader() {
  return "keyframe,keyframe_reason,localization,map_scale,landmarks_seen,road_points,pair_scale,"
         "ba_iterations,ba_cost_before,ba_cost_after,ba_ms,window_keyframes,window_landmarks,"
         "window_road_landmarks,ba_removed_observations,alignment_scale,window_road_pairs,"
         "map_pair_direction_deg,pair_outvoted_map,first_scale_refused";
}

std::string LocalizationName(MappedFrame::Localization localization) {
  switch (localization) {
    case MappedFrame::Localization::kKeyframe:
      return "keyframe";
    case MappedFrame::Localization::kMap:
      return "map";
    case MappedFrame::Localization::kInterpolated:
      return "interpolated";
    case MappedFrame::Localization::kStationary:
      return "stationary";
  }
  return "unknown";
}

std::string FormatMappedFrameCsv(const MappedFrame& frame) {
  const BundleAdjustmentReport& ba = frame.bundle_adjustment;
  const char* scale = frame.scale == MappedFrame::Scale::kRoad        ? "road"
                      : frame.scale == MappedFrame::Scale::kCarried   ? "carried"
                      : frame.scale == MappedFrame::Scale::kPairFixes ? "pair_fixes"
                                                                      : "none";
  std::ostringstream out;
  out << std::setprecision(6) << (frame.keyframe ? 1 : 0) << ',' << frame.keyframe_reason << ','
      << LocalizationName(frame.localization) << ',' << scale << ',' << frame.landmarks_seen << ','
      << frame.road_points << ',' << frame.pair_scale << ',' << ba.iterations << ','
      << ba.initial_cost << ',' << ba.final_cost << ',' << ba.milliseconds << ','
      << ba.num_keyframes << ',' << ba.num_landmarks << ',' << ba.num_road_landmarks << ','
      << ba.removed_observations << ',' << frame.alignment_scale << ',' << ba.num_road_pairs << ',';
  if (frame.map_pair_direction_deg) out << *frame.map_pair_direction_deg;
  out << ',' << (frame.pair_outvoted_map ? 1 : 0) << ',' << (frame.first_scale_refused ? 1 : 0);
  return out.str();
}

std::string MappingModeName(MappingOptions::Mode mode) {
  return mode == MappingOptions::Mode::kKeyframe ? "keyframe" : "frame_to_frame";
}

KeyframeBackend::KeyframeBackend(const PinholeCamera& camera, double camera_height,
                                 const MappingOptions& options,
                                 const ScaleEstimatorOptions& selection,
                                 const TwoViewMotionOptions& motion, int max_frames_before_scale)
    : camera_(camera),
      camera_height_(camera_height),
      options_(options),
      max_frames_before_scale_(max_frames_before_scale),
      selection_(camera,
                 SelectionOptions(selection, camera_height, options.road_min_points_per_pair)),
      motion_options_(motion),
      ground_normal_(selection_.options().road_model.max_angle_deg) {
  camera_.Check();
  options_.Check();
  if (options_.road_region_max_distance > 0.0) {
    road_region_ = RoadRegionAhead(camera_, options_.road_region_max_distance,
                                   options_.road_region_half_width);
  }
}

Rigid3d KeyframeBackend::PredictPose(const TwoViewMotion& motion) const {
  Rigid3d cur_from_prev = last_cur_from_prev_;
  const double length = last_cur_from_prev_.translation().norm();
  switch (motion.status) {
    case MotionStatus::kStationary:
    case MotionStatus::kFirstFrame:
      cur_from_prev = Rigid3d::Identity();
      break;
    case MotionStatus::kOk:
      cur_from_prev =
          MakeRigid3d(motion.rotation, motion.direction * (length > 0.0 ? length : 1.0));
      break;
    case MotionStatus::kPureRotation:
      cur_from_prev = MakeRigid3d(motion.rotation, last_cur_from_prev_.translation());
      break;
    default:
      break;
  }
  return cur_from_prev * last_cam_from_world_;
}

bool KeyframeBackend::PairOutvotesMap(std::optional<double> map_pair_direction_deg,
                                      const TwoViewMotion& motion) const {
  const double max_deg = options_.localization.max_direction_change_deg;
  if (motion.status != MotionStatus::kOk || !map_pair_direction_deg ||
      *map_pair_direction_deg <= max_deg) {
    return false;
  }
  // Two against one: the map's direction is dropped only when the car's last step goes the
  // pair's way too. A pair that RANSAC fitted to a truck filling the view disagrees with both.
  return last_cur_from_prev_.translation().norm() > 0.0 &&
         AgreesWithTwoViewDirection(last_cur_from_prev_, motion.direction, max_deg);
}

bool KeyframeBackend::BootstrapPose(const FrontendFrame& frontend, Rigid3d* cam_from_world) const {
  const Keyframe& last = window_.keyframes().back();
  std::vector<Correspondence> correspondences;
  for (const TrackObservation& observation : frontend.observations) {
    const auto seen = last.observations.find(observation.track_id);
    if (seen != last.observations.end()) {
      correspondences.push_back({observation.track_id, seen->second, observation.pixel});
    }
  }
  const TwoViewMotion motion = EstimateTwoViewMotion(correspondences, camera_, motion_options_);
  if (motion.status != MotionStatus::kOk) return false;
  const double predicted = (Centre(*cam_from_world) - Centre(last.cam_from_world)).norm();
  *cam_from_world = motion.CurFromPrev(predicted > 0.0 ? predicted : 1.0) * last.cam_from_world;
  return true;
}

std::vector<MappedFrame> KeyframeBackend::AddFrame(const FrontendFrame& frontend,
                                                   const cv::Mat& road_mask, const cv::Mat& image,
                                                   double timestamp, const cv::Mat& dynamic_mask) {
  PendingFrame pending;
  MappedFrame& mapped = pending.mapped;
  mapped.frame_index = frontend.frame_index;
  pending.observations = frontend.observations;
  std::vector<MappedFrame> out;
  for (int64_t id : frontend.late_dynamic_track_ids) window_.RemoveTrack(id);

  if (!has_frame_) {
    has_frame_ = true;
    window_.AddKeyframe(
        MakeKeyframe(frontend, road_mask, image, dynamic_mask, timestamp, Rigid3d::Identity()));
    mapped.keyframe = true;
    mapped.keyframe_reason = "first";
    pending.keyframe_before = frontend.frame_index;
    pending_.push_back(std::move(pending));
    return out;
  }

  mapped.stationary = frontend.motion.status == MotionStatus::kStationary;
  Rigid3d cam_from_world = PredictPose(frontend.motion);
  if (!mapped.stationary) {
    const FrameLocalization localization = LocalizeFrame(
        frontend.observations, window_.landmarks(), camera_, cam_from_world, options_.localization);
    mapped.landmarks_seen = localization.num_landmarks;
    if (localization.ok) {
      if (frontend.motion.status == MotionStatus::kOk) {
        mapped.map_pair_direction_deg =
            AngleToTwoViewDirectionDeg(localization.cam_from_world * last_cam_from_world_.inverse(),
                                       frontend.motion.direction);
      }
      mapped.pair_outvoted_map = PairOutvotesMap(mapped.map_pair_direction_deg, frontend.motion);
      if (!mapped.pair_outvoted_map) cam_from_world = localization.cam_from_world;
    }
  }

  const Keyframe& last_keyframe = window_.keyframes().back();
  const KeyframeMotion motion = MeasureKeyframeMotion(
      last_keyframe, frontend.frame_index, frontend.observations,
      cam_from_world.linear() * last_keyframe.cam_from_world.linear().transpose(), camera_);
  KeyframeReason reason = SelectKeyframe(motion, mapped.stationary, options_.keyframes);
  if (reason != KeyframeReason::kNone && window_.landmarks().empty() &&
      !BootstrapPose(frontend, &cam_from_world)) {
    reason = KeyframeReason::kNone;  // no two-view geometry yet: wait for more parallax
  }
  double step_length = (cam_from_world * last_cam_from_world_.inverse()).translation().norm();
  if (reason != KeyframeReason::kNone) {
    mapped.keyframe = true;
    mapped.keyframe_reason = KeyframeReasonName(reason);
    const int keyframe_before = last_keyframe.frame_index;
    const double arrival_baseline =
        (Centre(cam_from_world) - Centre(last_keyframe.cam_from_world)).norm();
    AddKeyframe(frontend, road_mask, image, dynamic_mask, timestamp, cam_from_world, &mapped);
    cam_from_world = window_.keyframes().back().cam_from_world;
    // The step's length is the one the frame arrived with, in the scale the adjustment gave
    // the keyframe interval. The adjusted keyframe against the previous frame's arrival pose
    // would add the adjustment's whole correction of the window to one step: on the real
    // traffic drive a 0.12 m step became 0.67 m, and the next 14 frames, which the map could
    // not localise, each moved that far while the car was stopping. Its direction stays the
    // adjusted one: where the map's direction drifts (a truck's tracks in it), the adjustment's
    // correction is the step's vote for the frame pair against the map (PairOutvotesMap).
    const Keyframe* before = window_.FindKeyframe(keyframe_before);
    if (before != nullptr && arrival_baseline > 0.0) {
      step_length *=
          (Centre(cam_from_world) - Centre(before->cam_from_world)).norm() / arrival_baseline;
    }
  }

  if (!mapped.stationary) {
    last_cur_from_prev_ = cam_from_world * last_cam_from_world_.inverse();
    const double adjusted_length = last_cur_from_prev_.translation().norm();
    if (adjusted_length > 0.0) last_cur_from_prev_.translation() *= step_length / adjusted_length;
  }
  last_cam_from_world_ = cam_from_world;
  pending.keyframe_before = window_.keyframes().back().frame_index;
  pending.keyframe_from_cam = window_.keyframes().back().cam_from_world * cam_from_world.inverse();
  pending_.push_back(std::move(pending));
  if (mapped.keyframe) out = SlideWindow(false);
  return out;
}

void KeyframeBackend::AddKeyframe(const FrontendFrame& frontend, const cv::Mat& road_mask,
                                  const cv::Mat& image, const cv::Mat& dynamic_mask,
                                  double timestamp, const Rigid3d& cam_from_world,
                                  MappedFrame* mapped) {
  Keyframe keyframe =
      MakeKeyframe(frontend, road_mask, image, dynamic_mask, timestamp, cam_from_world);
  keyframe.baseline_at_creation =
      (Centre(cam_from_world) - Centre(window_.keyframes().back().cam_from_world)).norm();
  window_.AddKeyframe(std::move(keyframe));
  TriangulateNewLandmarks(camera_, options_.landmarks, &window_);
  if (const std::optional<Plane> ground = GroundUnderNewestKeyframe()) {
    RemoveLandmarksBelowGround(*ground, options_.landmarks, &window_);
  }
  mapped->road_points = MarkRoadLandmarks(mapped);
  if (options_.road_alignment) AlignRoadPair(mapped);
  if (!scaled_) {
    if (mapped->road_points > 0 && PlausibleSpeed(mapped->pair_scale)) {
      pair_fixes_before_scale_.push_back(mapped->pair_scale);
    }
    DropImplausibleFirstRoad(mapped);
    ScaleMapOnFirstRoad();
  }
  mapped->bundle_adjustment =
      AdjustLocalWindow(camera_, camera_height_, options_.bundle_adjustment, &window_);
  last_scale_from_road_ = mapped->bundle_adjustment.scale_from_road;
  if (last_scale_from_road_) {
    scaled_ = true;
    scaled_by_fallback_ = false;
  }
}

std::optional<Plane> KeyframeBackend::GroundUnderNewestKeyframe() {
  const std::deque<Keyframe>& keyframes = window_.keyframes();
  if (!scaled_ || keyframes.size() < 2) return std::nullopt;
  const Rigid3d cur_from_prev =
      keyframes.back().cam_from_world * keyframes[keyframes.size() - 2].cam_from_world.inverse();
  const std::optional<Eigen::Vector3d> normal =
      ExpectedRoadNormal(cur_from_prev, selection_.options().road_model);
  if (!normal) return std::nullopt;
  // The motion model's normal of the last pair (perpendicular to the travel, nearest the
  // camera's down axis), built in the earlier keyframe's frame and used in the newest one's:
  // the model's own error (the camera's pitch against the road, the crown) is larger than the
  // two frames' difference, a median 0.1 degree. Rotated into the newest frame it scored no
  // better (docs/benchmark-history.md, "A review of the back end").
  return Plane{ground_normal_.Next(*normal), camera_height_};
}

int KeyframeBackend::MarkRoadLandmarks(MappedFrame* mapped) {
  const std::deque<Keyframe>& keyframes = window_.keyframes();
  if (keyframes.size() < 2) return 0;
  const Keyframe& prev = keyframes[keyframes.size() - 2];
  const Keyframe& cur = keyframes.back();
  std::vector<Eigen::Vector2d> prev_pixels, cur_pixels;
  std::vector<int64_t> ids;
  for (const auto& [id, pixel] : cur.observations) {
    const auto seen = prev.observations.find(id);
    if (seen == prev.observations.end()) continue;
    prev_pixels.push_back(seen->second);
    cur_pixels.push_back(pixel);
    ids.push_back(id);
  }
  const Rigid3d cur_from_prev = cur.cam_from_world * prev.cam_from_world.inverse();
  const double baseline = cur_from_prev.translation().norm();
  if (!(baseline > 0.0)) return 0;
  const ScaleEstimate estimate =
      selection_.Estimate(prev_pixels, cur_pixels, cur_from_prev, prev.road_mask);
  std::vector<int64_t> candidates;
  for (int index : estimate.candidate_track_indices) candidates.push_back(ids[index]);
  recent_road_candidates_.push_back(std::move(candidates));
  while (recent_road_candidates_.size() > static_cast<size_t>(options_.road_pool_pairs)) {
    recent_road_candidates_.pop_front();
  }
  if (estimate.status != ScaleStatus::kOk) {
    // Pooled candidates failed their own pair's fit once: worth their noise only where the
    // window would otherwise lose its road scale.
    const bool window_short_of_road =
        window_.CountRoadLandmarks() < options_.bundle_adjustment.min_road_landmarks;
    return window_short_of_road ? MarkPooledRoadLandmarks(prev, cur_from_prev, mapped) : 0;
  }
  mapped->pair_scale = camera_height_ / (estimate.plane.height * baseline);
  std::vector<int64_t> road_ids;
  for (int index : estimate.road_track_indices) road_ids.push_back(ids[index]);
  return MarkRoad(road_ids, prev, estimate.plane.normal);
}

int KeyframeBackend::MarkPooledRoadLandmarks(const Keyframe& anchor, const Rigid3d& cur_from_prev,
                                             MappedFrame* mapped) {
  if (options_.road_pool_pairs < 2) return 0;
  const std::optional<Eigen::Vector3d> expected_normal =
      ExpectedRoadNormal(cur_from_prev, selection_.options().road_model);
  if (!expected_normal) return 0;
  std::set<int64_t> pooled;
  for (const std::vector<int64_t>& candidates : recent_road_candidates_) {
    pooled.insert(candidates.begin(), candidates.end());
  }
  std::vector<int64_t> ids;
  std::vector<Eigen::Vector3d> points;
  for (int64_t id : pooled) {
    const auto landmark = window_.landmarks().find(id);
    if (landmark == window_.landmarks().end()) continue;
    const Eigen::Vector3d point = anchor.cam_from_world * landmark->second.position;
    if (point.z() <= 0.0) continue;
    ids.push_back(id);
    points.push_back(point);
  }
  const RoadPlaneFit fit =
      FitRoadPlaneRansac(points, *expected_normal, selection_.options().ransac);
  if (fit.status != RoadPlaneFit::Status::kOk) return 0;
  mapped->pair_scale = camera_height_ / fit.plane.height;
  std::vector<int64_t> road_ids;
  for (int index : fit.inliers) road_ids.push_back(ids[index]);
  return MarkRoad(road_ids, anchor, fit.plane.normal);
}

int KeyframeBackend::MarkRoad(const std::vector<int64_t>& landmark_ids, const Keyframe& anchor,
                              const Eigen::Vector3d& normal_in_anchor) {
  std::vector<int64_t> ids;
  std::vector<double> heights;
  for (int64_t id : landmark_ids) {
    const auto landmark = window_.landmarks().find(id);
    if (landmark == window_.landmarks().end() || landmark->second.is_road) continue;
    ids.push_back(id);
    heights.push_back(normal_in_anchor.dot(anchor.cam_from_world * landmark->second.position));
  }
  if (ids.empty()) return 0;
  // The map's scale changes slowly between road fixes; a plane at a very different height
  // is something else (a truck's side, a bridge, traffic moving with the car) that the
  // selection let through. A few such points agree with each other and would pull the whole
  // window to their scale, which the robust loss cannot stop when they are nearly as many as
  // the true road points.
  if (!RoadHeightsAgree(heights, RoadLandmarkHeights(), RoadPairHeights(),
                        options_.road_max_height_ratio)) {
    return 0;
  }
  for (int64_t id : ids) {
    Landmark& landmark = window_.landmarks().at(id);
    landmark.is_road = true;
    landmark.road_anchor_frame = anchor.frame_index;
    landmark.road_normal_in_anchor = normal_in_anchor;
  }
  return static_cast<int>(ids.size());
}

std::vector<double> KeyframeBackend::RoadLandmarkHeights() const {
  std::vector<double> heights;
  for (const auto& [id, landmark] : window_.landmarks()) {
    const Keyframe* anchor = window_.FindKeyframe(landmark.road_anchor_frame);
    if (!landmark.is_road || anchor == nullptr) continue;
    heights.push_back(
        landmark.road_normal_in_anchor.dot(anchor->cam_from_world * landmark.position));
  }
  return heights;
}

void KeyframeBackend::AlignRoadPair(MappedFrame* mapped) {
  std::deque<Keyframe>& keyframes = window_.keyframes();
  if (keyframes.size() < 2) return;
  Keyframe& prev = keyframes[keyframes.size() - 2];
  Keyframe& cur = keyframes.back();
  // Without segmentation the road is looked for where it lies ahead of a car on a lane.
  const cv::Mat& prev_mask = prev.road_mask.empty() ? road_region_ : prev.road_mask;
  const cv::Mat& cur_mask = cur.road_mask.empty() ? road_region_ : cur.road_mask;
  if (prev.image.empty() || cur.image.empty() || prev_mask.empty() || cur_mask.empty()) return;
  // A pair that shares too few tracks has a guessed relative pose (across a black frame, a
  // lost track): aligning the road through it would measure the guess.
  if (CountSharedTracks(prev, cur) < motion_options_.min_correspondences) return;
  const Rigid3d cur_from_prev = cur.cam_from_world * prev.cam_from_world.inverse();
  const double baseline = cur_from_prev.translation().norm();
  if (!(baseline > 0.0)) return;
  const std::optional<Eigen::Vector3d> expected_normal =
      ExpectedRoadNormal(cur_from_prev, selection_.options().road_model);
  // Once the map is metric its baseline predicts |t| / h (and where the search near it finds
  // nothing, the whole range is searched: the map's scale may be the wrong one); before, the
  // alignment searches its whole range.
  const double expected = scaled_ ? baseline / camera_height_ : 0.0;
  // The region ahead holds whatever is there, the car in front too: a pixel that does not
  // move with the road must not count (RoadPlaneAlignmentOptions::Loss).
  const bool on_road_mask = !prev.road_mask.empty() && !cur.road_mask.empty();
  RoadPlaneAlignmentOptions alignment_options = options_.alignment;
  if (!on_road_mask) alignment_options.loss = RoadPlaneAlignmentOptions::Loss::kTukey;
  const Eigen::Vector3d normal_guess = expected_normal.value_or(Eigen::Vector3d::UnitY());
  RoadPlaneAlignment alignment =
      AlignRoadPlaneOrSearchAll(prev.image, cur.image, prev_mask, cur_mask, camera_, cur_from_prev,
                                normal_guess, expected, alignment_options);
  const double shadow_brightness = options_.road_alignment_shadow_brightness;
  if (!alignment.ok && on_road_mask && shadow_brightness > 0.0) {
    ShadowFreeRoad& prev_road = prev.shadow_free_road;
    ShadowFreeRoad& cur_road = cur.shadow_free_road;
    if (prev_road.HasShadows(shadow_brightness) || cur_road.HasShadows(shadow_brightness)) {
      alignment =
          AlignRoadPlaneOrSearchAll(prev.image, cur.image, prev_road.Road(shadow_brightness),
                                    cur_road.Road(shadow_brightness), camera_, cur_from_prev,
                                    normal_guess, expected, alignment_options);
    }
  }
  if (!alignment.ok) return;
  cur.road_pair = RoadPairPlane{prev.frame_index, alignment.plane.height};
  cur.road_pair->on_road_mask = on_road_mask;
  mapped->alignment_scale = camera_height_ / (alignment.plane.height * baseline);
}

std::vector<double> KeyframeBackend::RoadPairHeights() const {
  std::vector<double> heights;
  for (const Keyframe& keyframe : window_.keyframes()) {
    if (!keyframe.road_pair || !keyframe.road_pair->in_adjustment) continue;
    const Keyframe* anchor = window_.FindKeyframe(keyframe.road_pair->anchor_frame);
    if (anchor == nullptr) continue;
    heights.push_back(keyframe.road_pair->height_per_baseline *
                      (Centre(keyframe.cam_from_world) - Centre(anchor->cam_from_world)).norm());
  }
  return heights;
}

bool KeyframeBackend::PlausibleSpeed(double metres_per_unit) const {
  const std::deque<Keyframe>& keyframes = window_.keyframes();
  const Keyframe& prev = keyframes[keyframes.size() - 2];
  const Keyframe& cur = keyframes.back();
  const double seconds = cur.timestamp - prev.timestamp;
  if (options_.first_scale_max_speed <= 0.0 || !(seconds > 0.0)) return true;
  const double baseline = (Centre(cur.cam_from_world) - Centre(prev.cam_from_world)).norm();
  return !(metres_per_unit * baseline / seconds > options_.first_scale_max_speed);
}

void KeyframeBackend::DropImplausibleFirstRoad(MappedFrame* mapped) {
  std::deque<Keyframe>& keyframes = window_.keyframes();
  if (keyframes.back().road_pair && !PlausibleSpeed(mapped->alignment_scale)) {
    keyframes.back().road_pair.reset();
    mapped->first_scale_refused = true;
  }
  if (mapped->road_points > 0 && !PlausibleSpeed(mapped->pair_scale)) {
    const int anchor = keyframes[keyframes.size() - 2].frame_index;
    for (auto& [id, landmark] : window_.landmarks()) {
      if (landmark.is_road && landmark.road_anchor_frame == anchor) landmark.is_road = false;
    }
    mapped->road_points = 0;
    mapped->first_scale_refused = true;
  }
}

void KeyframeBackend::ScaleMapOnFirstRoad() {
  const bool enough_landmarks =
      window_.CountRoadLandmarks() >= options_.bundle_adjustment.min_road_landmarks;
  std::vector<double> heights = enough_landmarks ? RoadLandmarkHeights() : RoadPairHeights();
  heights.erase(std::remove_if(heights.begin(), heights.end(), [](double h) { return !(h > 0.0); }),
                heights.end());
  if (heights.empty()) return;
  RescaleMap(camera_height_ / Median(heights));
}

void KeyframeBackend::ScaleMapOnPairFixes() {
  if (!options_.fallback_to_pair_fixes || pair_fixes_before_scale_.empty()) return;
  RescaleMap(Median(pair_fixes_before_scale_));
  scaled_ = true;
  scaled_by_fallback_ = true;
}

void KeyframeBackend::RescaleMap(double factor) {
  window_.Rescale(factor);
  for (PendingFrame& frame : pending_) {
    frame.keyframe_from_cam.translation() *= factor;
  }
  // The frame before this one, from which the next step is measured, moves with the map.
  last_cam_from_world_ = window_.RescaledPose(last_cam_from_world_, factor);
}

MappedFrame::Scale KeyframeBackend::CurrentScale() const {
  if (!scaled_) return MappedFrame::Scale::kNone;
  if (last_scale_from_road_) return MappedFrame::Scale::kRoad;
  return scaled_by_fallback_ ? MappedFrame::Scale::kPairFixes : MappedFrame::Scale::kCarried;
}

std::vector<MappedFrame> KeyframeBackend::SlideWindow(bool final) {
  std::vector<MappedFrame> out;
  const bool waited_enough = max_frames_before_scale_ <= 0 ||
                             static_cast<int>(pending_.size()) >= max_frames_before_scale_;
  if (!final && !scaled_ && !waited_enough) return out;
  // Frames are about to leave without a scale although pairs saw the road.
  if (!scaled_) ScaleMapOnPairFixes();
  while (window_.keyframes().size() > static_cast<size_t>(options_.window_size)) {
    Release(window_.keyframes()[1].frame_index, &out);
    window_.RemoveOldestKeyframe();
  }
  return out;
}

void KeyframeBackend::Release(int last_frame, std::vector<MappedFrame>* out) {
  while (!pending_.empty() && pending_.front().mapped.frame_index <= last_frame) {
    PendingFrame& frame = pending_.front();
    MappedFrame mapped = frame.mapped;
    mapped.scale = CurrentScale();
    const Keyframe* own = window_.FindKeyframe(mapped.frame_index);
    const Keyframe* before = window_.FindKeyframe(frame.keyframe_before);
    // The first frame is a keyframe and leaves before its keyframe does: every frame after it
    // has an output before it.
    if (own != nullptr) {
      mapped.world_from_cam = own->cam_from_world.inverse();
      mapped.localization = MappedFrame::Localization::kKeyframe;
    } else if (mapped.stationary) {
      mapped.world_from_cam = last_output_world_from_cam_;
      mapped.localization = MappedFrame::Localization::kStationary;
    } else {
      // The arrival pose relative to its keyframe, in the scale of the interval then.
      Rigid3d keyframe_from_cam = frame.keyframe_from_cam;
      Rigid3d guess_cam_from_world = last_output_world_from_cam_.inverse();
      if (before != nullptr) {
        const auto next =
            std::find_if(window_.keyframes().begin(), window_.keyframes().end(),
                         [&](const Keyframe& k) { return k.frame_index > before->frame_index; });
        if (next != window_.keyframes().end() && next->baseline_at_creation > 0.0) {
          keyframe_from_cam.translation() *=
              (Centre(next->cam_from_world) - Centre(before->cam_from_world)).norm() /
              next->baseline_at_creation;
        }
        guess_cam_from_world = (before->cam_from_world.inverse() * keyframe_from_cam).inverse();
      }
      const FrameLocalization localization =
          LocalizeFrame(frame.observations, window_.landmarks(), camera_, guess_cam_from_world,
                        options_.localization);
      mapped.world_from_cam =
          (localization.ok ? localization.cam_from_world : guess_cam_from_world).inverse();
      mapped.localization = localization.ok ? MappedFrame::Localization::kMap
                                            : MappedFrame::Localization::kInterpolated;
    }
    last_output_world_from_cam_ = mapped.world_from_cam;
    out->push_back(std::move(mapped));
    pending_.pop_front();
  }
}

std::vector<MappedFrame> KeyframeBackend::Finish() {
  std::vector<MappedFrame> out = SlideWindow(true);
  Release(pending_.empty() ? 0 : pending_.back().mapped.frame_index, &out);
  return out;
}

}  // namespace roadscale
