#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/scale/depth_consistency_vote.h"
#include "roadscale/scale/road_homography_refit.h"
#include "roadscale/scale/road_model_check.h"
#include "roadscale/scale/road_plane.h"
#include "roadscale/scale/road_plane_ransac.h"
#include "roadscale/scale/scale_filter.h"
#include "roadscale/scale/triangulation.h"

#include <Eigen/Core>

namespace roadscale {

// Every threshold of section III with the paper's value as default. The use_* switches turn
// single stages off for the paper's ablations: Table V (no selection / road-model check /
// + vote), Table VII (with / without segmentation), Table VIII (filter sigma).
struct ScaleEstimatorOptions {
  // h0 of eq. (13): the camera's height above the road in metres (KITTI's documented 1.65).
  double camera_height = 1.65;

  bool use_segmentation = true;  // Alg. 1 lines 1-5: keep road-mask pixels (when given)
  // Beyond the paper, ON by default (false = the paper's least-squares plane): refit the
  // plane on RANSAC's inliers in pixels, through the plane-induced homography, with its normal
  // perpendicular to the direction of travel (road_homography_refit.h). It halves the
  // per-frame noise on KITTI 00 (raw median error 6.2 % -> 2.9 % with the frontend's motion;
  // t_err 1.95 % -> 1.31 %) and on rendered drives (three seeds of urban and bumpy: t_err
  // 2.29 % -> 0.78 %); docs/benchmark-history.md, "Scale variants in the full system".
  bool homography_refit = true;
  RoadHomographyRefitOptions homography;
  bool use_horizon = true;           // keep points below the horizon only
  bool use_depth_vote = true;        // Alg. 1: the depth-consistency vote
  bool use_road_model_check = true;  // Alg. 2: triangles parallel to the expected road
  bool use_filter = true;            // eqs. (14)-(16): the mixed filter

  TriangulationOptions triangulation;
  DepthConsistencyVoteOptions depth_vote;
  RoadModelCheckOptions road_model;
  RoadPlaneRansacOptions ransac;
  ScaleFilterOptions filter;

  void Check() const;
};

enum class ScaleStatus {
  kOk,                // the road plane was fitted in this frame
  kHeldTooFewPoints,  // fewer than ransac.min_points road points: previous model kept
  kHeldDegenerate,    // no usable plane: previous model kept
  kNoMotion,          // zero or undefined translation: nothing to scale
};

// "ok", "held: too few points", "held: degenerate", "no motion".
const char* ScaleStatusName(ScaleStatus status);

// The scale of one frame pair and what led to it.
struct ScaleEstimate {
  ScaleStatus status = ScaleStatus::kNoMotion;
  // False until a first road plane has been fitted: raw_scale and scale are then NaN.
  bool has_scale = false;
  // s = h0 / h (eq. 13) of this frame, or of the last fitted model when held.
  double raw_scale = 0.0;
  // The mixed filter's output (raw_scale when the filter is off). The metric translation of
  // the frame pair is scale * t / |t|.
  double scale = 0.0;

  // Point counts after each stage.
  int num_tracks = 0;
  int num_triangulated = 0;
  int num_behind_camera = 0;
  int num_small_parallax = 0;
  int num_large_reprojection_error = 0;
  int num_preselected = 0;       // road mask + horizon
  int num_after_vote = 0;        // Alg. 1
  int num_after_road_model = 0;  // Alg. 2
  int num_ransac_inliers = 0;
  double inlier_ratio = 0.0;  // RANSAC inliers / points given to RANSAC
  bool used_road_mask = false;

  // The road plane in the previous camera's frame, in units of the baseline (the held one
  // when the frame is held).
  Plane plane;
  // Tracks (indices into the input pixel lists) whose points are the plane's inliers.
  std::vector<int> road_track_indices;
  // Tracks that passed the selection (road mask, horizon, Alg. 1, Alg. 2): what RANSAC was
  // given, also when it had too few of them.
  std::vector<int> candidate_track_indices;
};

// The road-plane scale of section III, frame pair after frame pair. It knows nothing of the
// visual odometry that feeds it: matched pixels of inlier tracks, the motion's rotation and
// translation direction, optionally a road mask. Keeps the last road model and the filter's
// window between calls; one instance serves one sequence, from one thread.
class ScaleEstimator {
 public:
  ScaleEstimator(const PinholeCamera& camera, const ScaleEstimatorOptions& options);

  // prev_pixels[i] and cur_pixels[i] are the same track in the previous and current image;
  // cur_from_prev is the motion (any translation length: only its direction is used);
  // prev_road_mask is CV_8UC1 of the previous image's size, non-zero = road, or empty when
  // there is no segmentation. Throws Error on lists of different sizes or a bad mask.
  ScaleEstimate Estimate(const std::vector<Eigen::Vector2d>& prev_pixels,
                         const std::vector<Eigen::Vector2d>& cur_pixels,
                         const Rigid3d& cur_from_prev, const cv::Mat& prev_road_mask);

  // Forgets the road model and the filter's window (a new sequence).
  void Reset();

  const ScaleEstimatorOptions& options() const { return options_; }

 private:
  PinholeCamera camera_;
  ScaleEstimatorOptions options_;
  ScaleFilter filter_;
  bool has_model_ = false;
  Plane last_plane_;
  double last_raw_scale_ = 0.0;
};

}  // namespace roadscale
