#pragma once

#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/mapping/frame_localizer.h"
#include "roadscale/mapping/keyframe_selector.h"
#include "roadscale/mapping/landmark_triangulator.h"
#include "roadscale/mapping/local_bundle_adjuster.h"
#include "roadscale/mapping/local_window.h"
#include "roadscale/mapping/steady_road_normal.h"
#include "roadscale/scale/road_plane_alignment.h"
#include "roadscale/scale/scale_estimator.h"

namespace roadscale {

struct MappingOptions {
  // keyframe: this back end (the default). frame_to_frame: the paper's MonoVO host, each
  // step's length from its own frame pair's road plane and the mixed filter (the ablation).
  enum class Mode { kKeyframe, kFrameToFrame };
  Mode mode = Mode::kKeyframe;
  // Keyframes in the bundle-adjusted window. A frame's pose is written when its keyframe
  // interval leaves the window, adjusted window_size - 1 times by then.
  int window_size = 10;
  // The road selection of a keyframe pair may pass on fewer points than the per-pair scale's
  // RANSAC minimum (Scale.ransac_min_points): no single pair decides the scale here, the
  // window's road landmarks together do (min_road_landmarks). 6 still lets RANSAC tell a
  // plane from a few stray points.
  int road_min_points_per_pair = 6;
  // Where a keyframe pair's own selection has fewer road points than that (little road
  // texture, a highway's few near points, traffic in front) and the window has fewer road
  // landmarks than it needs for its scale (bundle_adjustment.min_road_landmarks), RANSAC runs
  // once more on the selected candidates of the last road_pool_pairs pairs together, as the
  // map's landmarks in the anchor keyframe's frame. 1 turns the pooling off.
  int road_pool_pairs = 3;
  // A keyframe pair's road points are marked only if their median height under the anchor
  // (map units) is within this factor of the window's road landmarks' median height. The
  // map's scale moves by a few percent between road fixes, and 90 % of the pairs' planes lie
  // within 0.90-1.09 of the map on the rendered urban, bumpy and hills drives; on highway
  // seed 1 a pair's "road" at 8 times the height (six points on one plane) outvoted eight
  // true road points and shrank the map eightfold.
  double road_max_height_ratio = 1.5;
  // Until the map has its first road scale, a keyframe pair's road measurement (its selected
  // road points' plane, or its road alignment) that makes the car faster than this between
  // the two keyframes (m/s, by the frames' timestamps; 0: no limit) is not taken. A wrong
  // first scale is the one the map keeps until a road corrects it, and in a jam no road may
  // come for long: with network-like masks a rendered jam took one alignment at 200 times
  // its pair's own road points and drove 187 times too far. 70 m/s (250 km/h) is above any
  // car's speed on a road and far below such errors; an input without timestamps is timed
  // at 10 Hz (kDefaultFrameRateHz), so a slower one needs a higher limit or 0.
  double first_scale_max_speed = 70.0;
  // Where the map has had no road scale of its own when its first frames must be written
  // (max_frames_before_scale, or the sequence's end), it takes the median of the keyframe
  // pairs' own road fixes so far (each pair's selected road points, however few; those of a
  // too fast car left out) rather than writing unit steps, and marks those frames
  // (MappedFrame::Scale::kPairFixes) until a road scale of the map's own comes. In a rendered
  // jam with network-like masks the map's window never held the 12 road landmarks it needs
  // while single pairs saw 3-7 road points. false: such frames stay unscaled.
  bool fallback_to_pair_fixes = true;
  // Each keyframe pair's road plane also measured on the road's pixels (road_plane_alignment.h)
  // when both keyframes have a road mask and an image: a pair term in the adjustment
  // (bundle_adjustment.road_pair_sigma_m). It needs no road track to survive between the two
  // keyframes.
  bool road_alignment = true;
  RoadPlaneAlignmentOptions alignment;
  // Where the road alignment finds no plane on a pair's whole road, it tries once more
  // without the moving objects' shadows on it (MovingObjectShadows: road darker than this
  // share of the road's median grey level, in regions that touch a moving object). In dense
  // traffic the car ahead's shadow moves with the car and was the strongest texture on the
  // road: on the real KITTI traffic drive the alignment found a plane on 0 of 13 keyframe
  // pairs. A static shadow is road texture like any other, and the network's moving objects
  // are at times whole buildings, so the whole road stays the first try. 0: no second try.
  double road_alignment_shadow_brightness = 0.6;
  // Without segmentation (no road mask) the alignment samples the region where a level road
  // lies ahead (RoadRegionAhead): at most this many camera heights ahead and this many to
  // either side (40 and 2.5: 66 m and 4.1 m at h0 = 1.65 m, the own lane and half of each
  // neighbour; at full resolution the alignment's own lane limit applies as well), with
  // Tukey's biweight, so that the car ahead and the parked cars in the region do not count.
  // Without segmentation it took KITTI 00/200 from 2.29 % to 1.76 % (1.56 % with the region's
  // pairs keeping their vote, local_bundle_adjuster.cc), six rendered town drives from a mean
  // of 0.58 % to 0.50 %, and gave the rendered highways and jams a scale where the sparse road
  // points alone lost it; with the Huber loss the parked cars and the car ahead made the town
  // drives worse (mean 0.77 %; docs/benchmark-history.md, "The road ahead without segmentation").
  // 0 turns it off.
  double road_region_max_distance = 40.0;
  double road_region_half_width = 2.5;
  KeyframeSelectorOptions keyframes;
  LandmarkTriangulatorOptions landmarks;
  FrameLocalizerOptions localization;
  LocalBundleAdjusterOptions bundle_adjustment;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// "keyframe" or "frame_to_frame".
std::string MappingModeName(MappingOptions::Mode mode);

// One frame's final pose and how it came about.
struct MappedFrame {
  int frame_index = 0;
  Rigid3d world_from_cam = Rigid3d::Identity();
  bool keyframe = false;
  bool stationary = false;
  // The map's scale when the pose was written: from the window's road landmarks or road
  // pairs (kRoad, "road" in frames.csv), carried by the map from earlier ones (kCarried,
  // "carried"), from the keyframe pairs' own road fixes where the map never had enough road
  // for its own (kPairFixes, "pair_fixes": MappingOptions::fallback_to_pair_fixes), or none
  // yet (kNone, "none").
  enum class Scale { kRoad, kCarried, kPairFixes, kNone } scale = Scale::kNone;
  // How the pose was found when the frame was written (LocalizationName: the frames.csv
  // column): bundle adjusted as a keyframe, localised against the final landmarks, its
  // arrival pose relative to the keyframe before it rescaled with that interval
  // (interpolated), or the previous pose (stationary).
  enum class Localization { kKeyframe, kMap, kInterpolated, kStationary };
  Localization localization = Localization::kKeyframe;
  int landmarks_seen = 0;  // landmarks visible when the frame arrived
  // At arrival: the angle between the direction of travel of the map's localisation and the
  // frame pair's two-view direction (nothing when either was missing), and whether the pair
  // outvoted the map (KeyframeBackend::PairOutvotesMap: the prediction was kept).
  std::optional<double> map_pair_direction_deg;
  bool pair_outvoted_map = false;
  std::string keyframe_reason = "none";
  int road_points = 0;           // keyframes: road landmarks the pair selection marked
  double pair_scale = 0.0;       // keyframes: h0 / h of the pair's plane, metres per map unit
  double alignment_scale = 0.0;  // keyframes: the same from the road alignment (0: none)
  // keyframes: a road measurement of the pair was not taken as the map's first scale
  // (MappingOptions::first_scale_max_speed).
  bool first_scale_refused = false;
  BundleAdjustmentReport bundle_adjustment;  // keyframes: the adjustment it started
};

// "keyframe", "map", "interpolated" or "stationary".
std::string LocalizationName(MappedFrame::Localization localization);

// The back end's columns of OUT/frames.csv, and one frame's values for them.
std::string MappedFrameCsvHeader();
std::string FormatMappedFrameCsv(const MappedFrame& frame);

// The keyframe back end (mapping/): keyframes by parallax, landmarks from several keyframes,
// every frame localised against them, a sliding-window bundle adjustment with the road's
// camera-height term, which makes the map metric. Frames come in order; their final poses
// come out in order, a window later. One instance serves one sequence from one thread.
class KeyframeBackend {
 public:
  // `camera_height` is h0; `selection` the paper's road selection (its RANSAC minimum is
  // replaced by options.road_min_points_per_pair); `motion` the frontend's two-view motion
  // options, which the map's first keyframe pair is measured with; `max_frames_before_scale`:
  // frames kept waiting for the map's first scale before the window slides without one (0:
  // never wait). Throws Error on invalid options or camera.
  KeyframeBackend(const PinholeCamera& camera, double camera_height, const MappingOptions& options,
                  const ScaleEstimatorOptions& selection, const TwoViewMotionOptions& motion,
                  int max_frames_before_scale);

  // Takes the frontend's result for the next frame and its road mask (empty: none). Returns
  // the frames whose poses became final, in order.
  // `image` is the frame's grey image (empty: no road alignment).
  // `timestamp`: the frame's time in seconds (MappingOptions::first_scale_max_speed; NaN:
  // unknown, no speed check).
  // `dynamic_mask`: the frame's moving objects (empty: none known), whose shadows the road
  // alignment leaves out where the whole road gives no plane
  // (MappingOptions::road_alignment_shadow_brightness).
  std::vector<MappedFrame> AddFrame(const FrontendFrame& frontend, const cv::Mat& road_mask,
                                    const cv::Mat& image = cv::Mat(),
                                    double timestamp = std::numeric_limits<double>::quiet_NaN(),
                                    const cv::Mat& dynamic_mask = cv::Mat());
  // Returns every frame still waiting (call after the last frame).
  std::vector<MappedFrame> Finish();

  // Frames taken and not returned yet.
  size_t num_waiting() const { return pending_.size(); }
  // The newest frame's pose as the map has it now, before later adjustments of the window
  // move it: world_from_cam in the frame of the final poses, in metres once `scaled()`, in
  // the map's own units before.
  Rigid3d NewestWorldFromCam() const { return last_cam_from_world_.inverse(); }
  bool scaled() const { return scaled_; }
  const LocalWindow& window() const { return window_; }

 private:
  struct PendingFrame {
    MappedFrame mapped;
    std::vector<TrackObservation> observations;
    int keyframe_before = 0;  // frame index of the last keyframe at arrival (itself if one)
    Rigid3d keyframe_from_cam = Rigid3d::Identity();  // at arrival
  };

  Rigid3d PredictPose(const TwoViewMotion& motion) const;
  // Whether the frame pair's own direction of travel outvotes the map's localisation of the
  // frame: the angle between their directions (nothing: no direction to compare) is more than
  // FrameLocalizerOptions::max_direction_change_deg and the last step's direction sides with
  // the pair.
  bool PairOutvotesMap(std::optional<double> map_pair_direction_deg,
                       const TwoViewMotion& motion) const;
  // A keyframe while the map is empty (the first pair, or after every landmark was lost) has
  // nothing to localise against: its pose relative to the last keyframe is the two frames'
  // own two-view motion, at the predicted distance. False when that fails.
  bool BootstrapPose(const FrontendFrame& frontend, Rigid3d* cam_from_world) const;
  void AddKeyframe(const FrontendFrame& frontend, const cv::Mat& road_mask, const cv::Mat& image,
                   const cv::Mat& dynamic_mask, double timestamp, const Rigid3d& cam_from_world,
                   MappedFrame* mapped);
  // Before the map's first scale: takes back the newest keyframe pair's road landmarks or
  // road alignment where either makes the car too fast (MappingOptions::first_scale_max_speed).
  void DropImplausibleFirstRoad(MappedFrame* mapped);
  // Whether a fix of the newest keyframe pair (metres per map unit; 0: none) keeps the car
  // below MappingOptions::first_scale_max_speed.
  bool PlausibleSpeed(double metres_per_unit) const;
  // MappingOptions::fallback_to_pair_fixes.
  void ScaleMapOnPairFixes();
  // Multiplies the map, the waiting frames and the last pose by `factor`.
  void RescaleMap(double factor);
  // Measures the road plane between the last two keyframes on their road pixels and keeps it
  // on the newer one (Keyframe::road_pair) when the alignment converged.
  void AlignRoadPair(MappedFrame* mapped);
  // Marks the landmarks the paper's selection finds on the road between the last two
  // keyframes; returns how many.
  int MarkRoadLandmarks(MappedFrame* mapped);
  // The road plane under the newest keyframe once the map is metric, else nothing. Its normal
  // is the last pair's (perpendicular to the travel) where that is steady (SteadyRoadNormal,
  // with the road model's angle as the largest turn between keyframes).
  std::optional<Plane> GroundUnderNewestKeyframe();
  // The pooled fallback of MarkRoadLandmarks (MappingOptions::road_pool_pairs).
  int MarkPooledRoadLandmarks(const Keyframe& anchor, const Rigid3d& cur_from_prev,
                              MappedFrame* mapped);
  // Marks `landmark_ids` as road landmarks under `anchor` with the road normal found there.
  int MarkRoad(const std::vector<int64_t>& landmark_ids, const Keyframe& anchor,
               const Eigen::Vector3d& normal_in_anchor);
  // Heights of the window's road landmarks under their anchors along their normals (map units).
  std::vector<double> RoadLandmarkHeights() const;
  // Camera heights of the window's road pairs (map units): height per baseline times baseline.
  std::vector<double> RoadPairHeights() const;
  // Gives an unscaled map the road's scale in one step before its first adjustment with it:
  // the adjustment alone would need many iterations for so large a change.
  void ScaleMapOnFirstRoad();
  std::vector<MappedFrame> SlideWindow(bool final);
  // Writes the waiting frames up to and including `last_frame`.
  void Release(int last_frame, std::vector<MappedFrame>* out);
  MappedFrame::Scale CurrentScale() const;

  PinholeCamera camera_;
  double camera_height_;
  MappingOptions options_;
  int max_frames_before_scale_;
  ScaleEstimator selection_;
  TwoViewMotionOptions motion_options_;
  SteadyRoadNormal ground_normal_;  // of GroundUnderNewestKeyframe
  LocalWindow window_;
  cv::Mat road_region_;  // RoadRegionAhead, or empty when off
  std::deque<PendingFrame> pending_;
  // Track ids of the road candidates of the last road_pool_pairs keyframe pairs.
  std::deque<std::vector<int64_t>> recent_road_candidates_;
  Rigid3d last_cam_from_world_ = Rigid3d::Identity();
  Rigid3d last_cur_from_prev_ = Rigid3d::Identity();  // cur_from_prev of the last moving frame
  bool has_frame_ = false;
  bool scaled_ = false;                // the road has scaled the map at least once
  bool last_scale_from_road_ = false;  // ... in the last adjustment
  bool scaled_by_fallback_ = false;    // by ScaleMapOnPairFixes, and by no road since
  // The keyframe pairs' road fixes (metres per map unit) while the map has no scale.
  std::vector<double> pair_fixes_before_scale_;
  Rigid3d last_output_world_from_cam_ = Rigid3d::Identity();
};

}  // namespace roadscale
