#pragma once

#include <opencv2/core.hpp>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/scale/road_plane.h"

#include <Eigen/Core>

namespace roadscale {

// Beyond the paper: the road plane of a frame pair measured on the road's pixels, not on its
// tracks.
//
// A road pixel of the current image along the ray r = K^-1 x (r.z = 1), on the plane
// n.X = h of the current camera, was seen in the previous image at pi(K R' (r - u (m.r))),
// with R' the previous-from-current rotation, u the unit direction of the translation t of
// cur_from_prev and m = |t| n / h: the plane-induced homography, linear in m. The alignment
// finds the m (with a grey offset) that
// makes the previous image, sampled there, match the current one on every textured road
// pixel, coarse to fine with Gauss-Newton and a robust loss. The current image's pixels are
// warped into the previous one because, driving forward, all the road the current image sees
// was in view before, while the previous image's nearest road has left the current one.
//
// Why beside the sparse selection: a track on the road must survive KLT between the two
// images, and the road right in front of the camera grows by a third from one frame to the
// next at highway speed, where translation-only KLT fails, and a few metres of road between
// the car and the one ahead in a traffic jam hold a handful of corners. The warp of the
// alignment is the road's own homography, so stretched road and low-contrast asphalt count,
// pixel by pixel.
struct RoadPlaneAlignmentOptions {
  // Coarsest pyramid level (0 = full resolution only); each level halves the image.
  int pyramid_levels = 3;
  // Pixels whose grey gradient (grey levels per pixel) is below this carry no information
  // about the warp and are not sampled.
  double min_gradient = 4.0;
  // At most this many road pixels per level, spread evenly over the ones that qualify.
  int max_samples = 4000;
  // Fewer usable pixels at the finest level: no estimate.
  int min_samples = 200;
  int max_iterations = 20;  // Gauss-Newton per level
  // Huber scale of the grey-level residual: beyond it, a pixel (a shadow edge, a car
  // crossing the road) counts linearly.
  double loss_scale_grey = 8.0;
  // kHuber suits pixels known to be road, where a residual beyond the scale is a shadow edge
  // or a mask a few pixels off. kTukey (Tukey's biweight, cut off at 4.685 / 1.345 times
  // loss_scale_grey, the same 95 % efficiency as the Huber scale) lets a pixel beyond the
  // cut-off count not at all: for samples that are only probably road (the region ahead
  // without segmentation), where a car ahead or a kerb fills part of them and each of their
  // pixels would otherwise still pull with the Huber loss's full slope.
  enum class Loss { kHuber, kTukey };
  Loss loss = Loss::kHuber;
  // The alignment starts, at the coarsest level where at least half of the samples land in
  // the other image, from the best of `search_steps` values of |t| / h spaced evenly in
  // logarithm between these bounds, the normal held at the guess.
  double min_baseline_over_height = 0.01;
  double max_baseline_over_height = 10.0;
  int search_steps = 40;
  // With an expected |t| / h (the map's scale), the search spans it divided and multiplied
  // by this instead: repeated road texture (dashed lane lines) has minima at multiples of
  // the true step.
  double expected_search_factor = 1.5;
  // Road mask pixels within this distance of the mask's edge are not sampled: their warped
  // position may fall on a car or a kerb, and a carried mask's edge is a few pixels off. On
  // the rendered highways 2 / 8 / 12 px gave mean t_err 4.4 / 2.1 / 1.5 %, on the town drives
  // 0.44 / 0.41 / 0.40 % (docs/benchmark-history.md, "The road's pixels").
  int mask_erosion_px = 12;
  // At full resolution only road pixels whose point on the guessed plane lies within this
  // many camera heights to either side of the camera (0: no limit), the car's own lane at
  // 1.65 m and 3.5 m lanes. A crowned road falls away to both edges, so a plane through the
  // whole carriageway lies below the road under the car and makes the camera too high: on the
  // rendered streets (2 % crown) |t| / h came out 0.3-0.5 % short on average with the whole
  // road, 0.0-0.1 % with this. The coarser levels keep the whole road, which finds the right
  // minimum where the lane alone has little texture (highways).
  double max_lateral_offset = 1.0;
  // Hold the plane's normal perpendicular to the translation (its roll about the direction of
  // travel free), as the sparse fit's ScaleEstimatorOptions::homography_tangent_to_travel: the
  // car drives on the road. A free normal is seen only through the road 6-33 m ahead and
  // extrapolated to the camera: on KITTI 00's right turn (frames 105-119, one-frame pairs on
  // the images' own motion) it tilted 3-5 degrees in pitch and every pair came out 8-26 %
  // short; held, within a few per cent. With the exact motion it is also three times closer
  // on rendered drives. But it takes the translation's direction as exact, and in the keyframe
  // back end that is the map's: there it cost urban 1 0.19 -> 0.71 % t_err and highway 1
  // 0.61 -> 1.82 %, so it is off by default (docs/benchmark-history.md, "The road alignment in
  // turns").
  bool tangent_to_travel = false;
  // A free normal tilted further than this (degrees) against the plane perpendicular to the
  // translation gives no plane (0: no limit). The road a car drives on is perpendicular to its
  // travel within the suspension's pitch and the motion's direction error (straight real pairs
  // 0.5-1.3 degrees); the free planes of KITTI 00's right turn tilted 2.5-4.9 degrees and came
  // out 8-26 % short. But where the direction itself is poor (a creeping car in a jam) a true
  // road tilts as much: 2 degrees took rendered traffic_jam 2 from 1.084 to 1.309 in length,
  // and helped KITTI only in part, so there is no limit by default (docs/benchmark-history.md,
  // "The road alignment in turns"); `rescale` sets 2 degrees (TrajectoryRescalerOptions).
  double max_pitch_to_travel_deg = 0.0;
  // Nor ones farther ahead than this many camera heights (0: no limit): on real frames the
  // road's heights stay within 2 % up to about 30 m and drift high beyond
  // (../shared/KITTI-NOTES.md); 20 heights are 33 m at 1.65 m.
  double max_distance = 20.0;

  // Throws Error naming the first invalid option.
  void Check() const;
};

struct RoadPlaneAlignment {
  bool ok = false;  // converged at the finest level, on enough pixels, to a road-like plane
  // In the previous camera's frame, the height in units of the translation's length.
  Plane plane;
  int samples = 0;                   // used at the finest level
  double pitch_to_travel_deg = 0.0;  // the normal's angle to the plane perpendicular to the travel
  int iterations = 0;                // summed over the levels
};

// prev_image and cur_image: grey CV_8UC1 of the camera's size. cur_road_mask: CV_8UC1 of the
// same size, non-zero = road (the pixels sampled); prev_road_mask: the same for the previous
// image, or empty (then every warped pixel inside the image counts). cur_from_prev: the
// motion, of any translation length (only its direction is used). normal_guess: the road
// normal expected in the previous camera's frame. expected_baseline_over_height: |t| / h if
// known (the map's scale), else 0 (the whole range is searched). The result's plane is in
// the previous camera's frame. Throws Error on images or masks of the wrong type or size.
RoadPlaneAlignment AlignRoadPlane(const cv::Mat& prev_image, const cv::Mat& cur_image,
                                  const cv::Mat& prev_road_mask, const cv::Mat& cur_road_mask,
                                  const PinholeCamera& camera, const Rigid3d& cur_from_prev,
                                  const Eigen::Vector3d& normal_guess,
                                  double expected_baseline_over_height,
                                  const RoadPlaneAlignmentOptions& options);

// AlignRoadPlane around `expected_baseline_over_height` first, and where that finds no plane,
// once more over the whole range (as without an expectation). The expectation comes from a
// map whose scale may be far off - a first scale from one creeping pair in a traffic jam, 3.4
// times the truth on a rendered one - and a search that spans only 1/1.5 to 1.5 times a wrong
// value never meets the road's own minimum again, so nothing would correct it. Where the
// first search succeeds, its result stands: the whole range has minima at multiples of the
// true step on dashed lane lines (searching it always made rendered highway 1 and traffic jam
// 2 worse; docs/benchmark-history.md, "A wrong scale is no longer for good").
RoadPlaneAlignment AlignRoadPlaneOrSearchAll(
    const cv::Mat& prev_image, const cv::Mat& cur_image, const cv::Mat& prev_road_mask,
    const cv::Mat& cur_road_mask, const PinholeCamera& camera, const Rigid3d& cur_from_prev,
    const Eigen::Vector3d& normal_guess, double expected_baseline_over_height,
    const RoadPlaneAlignmentOptions& options);

// Where a level road ahead of the camera is seen when no segmentation says where the road
// is: 255 at the pixels whose ray meets the plane y = h (camera frame, y down) no farther
// than `max_distance` camera heights ahead and within `half_width` camera heights to either
// side, else 0 (CV_8UC1 of the camera's size). Throws Error unless both are positive.
cv::Mat RoadRegionAhead(const PinholeCamera& camera, double max_distance, double half_width);

}  // namespace roadscale
