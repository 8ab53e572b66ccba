#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/mapping/landmark.h"

namespace roadscale {

struct FrameLocalizerOptions {
  // Fewer landmarks seen, or fewer inliers after the refinement: not localised (the caller
  // keeps its guess: the predicted pose, or the arrival pose relative to the keyframe).
  int min_landmarks = 12;
  // Motion-only refinement: Cauchy loss of this scale (pixels) - it must shed wrong matches
  // that the starting pose does not yet tell apart - and at most this many iterations.
  double loss_px = 1.0;
  int max_iterations = 10;
  // A landmark is an inlier of the refined pose when its error is below this (pixels).
  double inlier_threshold_px = 2.0;
  // Below this share of inliers the starting pose is taken as wrong and PnP with RANSAC
  // (EPnP on minimal samples, threshold inlier_threshold_px, seeded) finds a new one.
  double min_inlier_ratio = 0.6;
  int ransac_iterations = 100;
  // A localised pose whose direction of travel from the previous frame is further than this
  // (degrees) from the frame pair's own two-view direction, while the car's last step agrees
  // with the pair, is not taken; the prediction is kept. The map can bend where it sees few
  // landmarks (a truck passing close on a highway): one pose 5 degrees off, and the road
  // alignment, which warps with the map's direction, fails from then on. The last step's vote
  // keeps the map where the pair is the one that is wrong (RANSAC fitted to a truck filling
  // the view). On healthy rendered drives and KITTI map and pair differ by 1.5-3 degrees at
  // the 99th percentile (docs/benchmark-history.md, "The map's direction checked").
  double max_direction_change_deg = 5.0;

  // Throws Error naming the first invalid option.
  void Check() const;
};

struct FrameLocalization {
  bool ok = false;
  bool used_ransac = false;
  Rigid3d cam_from_world = Rigid3d::Identity();
  int num_landmarks = 0;  // landmarks the frame sees
  int num_inliers = 0;
};

// The angle in degrees between the direction of travel of `cur_from_prev` and
// `two_view_direction` (the frame pair's measured direction in the current camera, of any
// length); nothing when either has no direction (a step without translation).
std::optional<double> AngleToTwoViewDirectionDeg(const Rigid3d& cur_from_prev,
                                                 const Eigen::Vector3d& two_view_direction);

// Whether that angle is within `max_deg`. A step without translation has no direction to
// disagree with.
bool AgreesWithTwoViewDirection(const Rigid3d& cur_from_prev,
                                const Eigen::Vector3d& two_view_direction, double max_deg);

// The pose of a frame from the window's landmarks that it sees: motion-only refinement
// started at `initial_cam_from_world` (the previous pose moved by the two-view motion), and
// PnP with RANSAC when that start proves wrong.
FrameLocalization LocalizeFrame(const std::vector<TrackObservation>& observations,
                                const std::map<int64_t, Landmark>& landmarks,
                                const PinholeCamera& camera, const Rigid3d& initial_cam_from_world,
                                const FrameLocalizerOptions& options);

}  // namespace roadscale
