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
