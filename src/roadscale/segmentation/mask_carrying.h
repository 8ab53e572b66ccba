#pragma once

#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace roadscale {

// Masks of a segmented frame carried to later frames that the network does not see.
struct MaskCarryOptions {
  // The road's homography between two frames is fitted (RANSAC) to the tracks that start on
  // the earlier frame's road mask; fewer of them, or fewer inliers, than this: no fit.
  int road_min_tracks = 12;
  // RANSAC inlier threshold in pixels: KLT's tracks are accurate to a few tenths of a pixel,
  // the road's unevenness and the mask's edge add a little more.
  double road_ransac_threshold_px = 2.0;
  // The road's homography between two frames fitted as the road plane's under the motion the
  // frontend measured into the earlier frame (FitRoadHomographyOnMotion: its step length and a
  // small turn free), once a direction of travel has been measured; false: a free homography
  // (FitRoadHomography), as before. In a jam the free fit, on a few small patches of road
  // between the cars, carried the road mask onto the houses (docs/benchmark-history.md,
  // "Carried road masks in a jam").
  bool road_on_motion = true;
  // The moving-object mask grows by this many pixels per frame it is carried: what a car's
  // own motion can move its outline that the road's motion at its wheels does not explain.
  // 0 since the frontend checks every track against each segmented frame's own mask when it
  // arrives (FeatureTracker::DropOnMaskAt): the tracks a car's own motion carries out of its
  // carried mask are caught there, while 2 px a frame dropped twelve times as many static
  // tracks around parked cars and cost accuracy (docs/benchmark-history.md, "Segmenting keyframes
  // only").
  double dynamic_growth_px_per_frame = 0.0;
  // The moving-object mask is also kept where the segmented frame had it. Moving it with the
  // road is right for a parked car; a car in traffic keeps pace with the camera and so keeps
  // its pixels while the road moves under it (a car or truck close ahead or alongside in a
  // jam). Which of the two an object does is unknown until the network sees the next frame,
  // so the carried mask holds both: on a real city drive in dense traffic the carried masks
  // otherwise let tracks and new features onto the vehicles beside and ahead, and the map
  // found no road (docs/benchmark-history.md, "Dense traffic: carried masks").
  bool dynamic_in_place = true;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// The homography cur_from_prev (pixels) of the road plane between two frames, fitted to the
// track pixels `prev` -> `cur` whose `prev` pixel lies on `prev_road_mask` (non-zero = road);
// nothing when too few tracks or inliers (RANSAC). A plane induces one homography between two
// views, so it is exact for road pixels whatever the motion.
std::optional<Eigen::Matrix3d> FitRoadHomography(const std::vector<Eigen::Vector2d>& prev,
                                                 const std::vector<Eigen::Vector2d>& cur,
                                                 const cv::Mat& prev_road_mask,
                                                 const MaskCarryOptions& options);

// The road's homography cur_from_prev in the form a plane induces, K R (I - s d n^T) K^-1
// (d the direction of travel and n the road normal, both unit vectors in the previous camera's
// frame; s the step's length over the camera height), fitted to the same tracks as
// FitRoadHomography: `s` and a small rotation correction (three angles) about the predicted
// `rotation` (cur_from_prev), the direction and the normal as given. Nothing when too few
// tracks or inliers.
//
// Why not the free homography: in a jam the road shows between the cars in a few small
// patches that move a few pixels a frame, within reach of any of the eight parameters' fits
// there, and the free fit's mapping away from those patches is whatever the sample left it:
// on a rendered jam it magnified the road by a third in one frame of 0.17 m, and the road
// mask carried through it covered the houses (docs/benchmark-history.md, "Carried road masks
// in a jam"). Four parameters of a plane's motion cannot move the road off the road.
std::optional<Eigen::Matrix3d> FitRoadHomographyOnMotion(
    const std::vector<Eigen::Vector2d>& prev, const std::vector<Eigen::Vector2d>& cur,
    const cv::Mat& prev_road_mask, const Eigen::Matrix3d& intrinsics,
    const Eigen::Matrix3d& rotation, const Eigen::Vector3d& direction,
    const Eigen::Vector3d& normal, const MaskCarryOptions& options);

// A road mask moved by the road's homography `cur_from_src` (nearest neighbour; pixels that
// come from outside the source image are not road).
cv::Mat CarryRoadMask(const cv::Mat& road_mask, const Eigen::Matrix3d& cur_from_src);

// A moving-object mask carried `frames` frames (at half resolution): cut into 16 px wide strips,
// each blob of a strip moved as the road under its lowest pixel moves (and scaled by the road
// homography's horizontal magnification there: a car stands upright on the road), joined by the
// mask where it was when `dynamic_in_place` (an object keeping pace with the camera), then the
// whole mask grown by dynamic_growth_px_per_frame per frame for the objects' own motion. Pieces
// whose base the homography cannot map stay in place.
cv::Mat CarryDynamicMask(const cv::Mat& dynamic_mask, const Eigen::Matrix3d& cur_from_src,
                         int frames, const MaskCarryOptions& options);

}  // namespace roadscale
