#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "roadscale/frontend/sampson_refinement.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"

#include <Eigen/Core>

namespace roadscale {

// What the two-view estimate of one frame is worth. Only kOk gives a translation direction;
// the pipeline keeps the pose when stationary and falls back on the others.
enum class MotionStatus {
  kOk,             // rotation and unit translation direction measured
  kFirstFrame,     // nothing to compare with yet
  kStationary,     // the image did not move: no rotation, no measurable translation
  kPureRotation,   // the image moved as a rotation only: rotation measured, direction not
  kTooFewTracks,   // fewer correspondences than min_correspondences
  kTooFewInliers,  // the essential matrix found too few inliers (or too small a share)
};

// "ok", "first_frame", "stationary", "pure_rotation", "too_few_tracks", "too_few_inliers".
std::string MotionStatusName(MotionStatus status);

// One track seen in the previous and in the current frame (pixels).
struct Correspondence {
  int64_t track_id = 0;
  Eigen::Vector2d prev = Eigen::Vector2d::Zero();
  Eigen::Vector2d cur = Eigen::Vector2d::Zero();
};

struct TwoViewMotionOptions {
  // RANSAC inlier threshold on the Sampson error, in pixels (OpenCV divides it by the focal
  // length). KLT with a forward-backward check is accurate to a few tenths of a pixel, so
  // 1 px is about 3 sigma.
  double ransac_threshold_px = 1.0;
  double ransac_confidence = 0.999;
  int ransac_max_iterations = 2000;
  // Seed of every random generator used here (OpenCV's cv::theRNG() included), so that the
  // same input always gives the same motion.
  uint64_t seed = 1;

  // Fewer correspondences than this: kTooFewTracks.
  int min_correspondences = 30;
  // Fewer essential-matrix inliers, or a smaller inlier share, than this: kTooFewInliers. At
  // a 30 % inlier share 2000 five-point samples still find an all-inlier one with 99 %
  // probability; below it a RANSAC "winner" may well be a moving object.
  int min_inliers = 30;
  double min_inlier_ratio = 0.3;

  // Median image motion (pixels) below which the camera is taken as stationary: KITTI's
  // tracks jitter by ~0.1 px, a 0.05 deg rotation moves the image 0.6 px.
  double stationary_flow_px = 0.5;
  // Median parallax (pixels of image motion left after removing the best pure rotation)
  // below which the translation is not measurable and the frame is a pure rotation. At 1 px
  // the direction of the epipole is no longer determined by tracks accurate to ~0.1-0.3 px.
  double min_parallax_px = 1.0;

  // Refine (R, t) by least squares on the Sampson error after RANSAC and the decomposition:
  // the RANSAC model comes from five points only. On synthetic scenes with 0.1 px noise this
  // takes the direction error from ~1.8 deg to ~0.05 deg (median), the accuracy of the
  // least-squares optimum started from the truth.
  bool refine = true;
  // After a first round on every correspondence (Cauchy loss at the RANSAC threshold), the
  // refinement is repeated on the correspondences within this many robust standard
  // deviations (1.4826 x median absolute Sampson error) of the model, capped at the RANSAC
  // threshold, until that set is stable: wrong tracks that pass the loose RANSAC threshold
  // otherwise bias the direction. 0 = the RANSAC threshold.
  double refinement_inlier_sigmas = 3.0;
  // Tracks within this angle (degrees) of the epipole are left out of the refinement. Driving
  // forward, the epipole lies inside the image, and there a wrong track fits the epipolar
  // geometry after a small move of the epipole: such tracks create false minima a few degrees
  // from the true direction. On synthetic forward motion with 30 % outliers, 5 deg takes the
  // median direction error from ~0.5 deg to ~0.09 deg, at a small cost without outliers.
  double refinement_epipole_exclusion_deg = 5.0;
  SampsonRefinementOptions refinement;

  // Throws Error naming the first invalid option.
  void Check() const;
};

struct TwoViewMotion {
  MotionStatus status = MotionStatus::kFirstFrame;
  // cur_from_prev: X_cur = rotation * X_prev + direction * (unknown length). The direction is
  // a unit vector for kOk (also filled, but not to be trusted, for kTooFewInliers) and zero
  // otherwise; the rotation is identity when stationary or when no estimate exists.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();

  std::vector<int64_t> inlier_track_ids;  // correspondences consistent with the motion
  int num_correspondences = 0;
  int num_inliers = 0;
  double inlier_ratio = 0.0;
  // Median image motion of the correspondences (pixels) and median parallax: the motion left
  // after removing the rotation (pixels; over the inliers where an essential matrix was found,
  // the flow itself for kStationary, 0 when the estimate stopped before).
  double flow_px = 0.0;
  double parallax_px = 0.0;
  // Root mean square Sampson error of the inliers before / after refinement (pixels).
  double sampson_rms_px = 0.0;
  double refined_sampson_rms_px = 0.0;

  // The rigid motion with a translation of the given length along `direction`.
  Rigid3d CurFromPrev(double length = 1.0) const;
};

// Relative motion of a calibrated camera between two frames from its correspondences: the
// stationary and pure-rotation cases are recognised first, then the essential matrix by
// 5-point RANSAC (cv::findEssentialMat), its decomposition with a cheirality test, and the
// Sampson refinement.
// Throws Error on invalid options or camera.
TwoViewMotion EstimateTwoViewMotion(const std::vector<Correspondence>& correspondences,
                                    const PinholeCamera& camera,
                                    const TwoViewMotionOptions& options);

}  // namespace roadscale
