#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/mapping/local_window.h"

#include <Eigen/Core>

namespace roadscale::testing {

// A straight street with exact geometry for the mapping tests: road points h0 below the
// camera (y down), walls on both sides, and a camera driving along +z with a gentle yaw.
struct MappingTestScene {
  PinholeCamera camera = KittiOdometryCamera();
  double camera_height = 1.65;
  std::vector<Eigen::Vector3d> points;  // world frame; index = track id
  std::vector<bool> is_road;
  std::vector<Rigid3d> cam_from_world;  // one per frame

  // `step_m` metres a frame, `yaw_deg_per_frame` of turn; frame 0 is the world.
  static MappingTestScene Street(int frames, double step_m, double yaw_deg_per_frame,
                                 uint32_t seed = 7);

  // What the camera of `frame` sees: every point in front within the image, with Gaussian
  // pixel noise of `noise_px`, in increasing id order.
  std::vector<TrackObservation> Observe(int frame, double noise_px, uint32_t seed) const;
  // The frontend's result for `frame`: its observations and the exact two-view motion from
  // the previous frame (stationary when the camera did not move).
  FrontendFrame Frontend(int frame, double noise_px, uint32_t seed) const;
};

// A window of `keyframes` of the scene's frames (every `spacing`-th) with exact poses,
// landmarks for every point seen by two of them, exact (noise-free) observations, and the
// road points marked with the true normal under the first keyframe that sees them.
LocalWindow ExactWindow(const MappingTestScene& scene, int keyframes, int spacing);

}  // namespace roadscale::testing
