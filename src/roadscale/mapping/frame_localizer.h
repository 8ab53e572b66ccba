#pragma once

#include <cstdint>
#include <map>
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

// The pose of a frame from the window's landmarks that it sees: motion-only refinement
// started at `initial_cam_from_world` (the previous pose moved by the two-view motion), and
// PnP with RANSAC when that start proves wrong.
FrameLocalization LocalizeFrame(const std::vector<TrackObservation>& observations,
                                const std::map<int64_t, Landmark>& landmarks,
                                const PinholeCamera& camera, const Rigid3d& initial_cam_from_world,
                                const FrameLocalizerOptions& options);

}  // namespace roadscale
