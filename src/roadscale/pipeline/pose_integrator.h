#pragma once

#include <string>

#include "roadscale/frontend/two_view_motion.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/pipeline/scale_source.h"

namespace roadscale {

// How a frame's pose follows from the previous frame's.
enum class PoseUpdate {
  kFirst,             // the first frame: world = this camera
  kMotion,            // the measured rotation and direction, with the scale source's length
  kKept,              // stationary: the pose of the previous frame
  kRotationOnly,      // pure rotation: the measured rotation, the last measured direction,
                      // a length scaled down by the parallax
  kConstantVelocity,  // no usable estimate: the last measured (kMotion) rotation and
                      // direction again, with this step's length
};

// "first", "motion", "kept", "rotation_only", "constant_velocity".
std::string PoseUpdateName(PoseUpdate update);

// `reference_length` times parallax_px / reference_parallax_px: parallax (the image motion
// left after removing the rotation) is the translation over the scene's depth, and the depth
// of the tracked scene changes little between neighbouring frames, so the ratio of parallaxes
// is the ratio of step lengths. `reference_length` when either parallax is not positive.
double ParallaxScaledLength(double reference_length, double parallax_px,
                            double reference_parallax_px);

// Chains the per-frame motions into world_from_cam poses:
// world_from_cam[t] = world_from_cam[t-1] * inverse(cur_from_prev[t]).
//
// The step length comes from the scale source; when it has none for a step, the last valid
// length is used. Before the first valid length the steps have unit length: the trajectory
// then has the measured shape at an arbitrary scale (flagged "unscaled" by the pipeline),
// which says more than a camera standing still. The degenerate frames are handled as the frontend's
// status asks: a stationary frame keeps the pose (a stop must not drift); a pure rotation
// turns the camera and keeps moving along the last measured direction (a car turning slowly
// still moves forward, and its direction in the camera frame changes little from one frame
// to the next); a frame without an estimate repeats the last measured step's rotation and
// direction.
//
// A pure rotation without a length of its own moves ParallaxScaledLength(last length, its
// parallax, the parallax of the last measured motion), at most the last length: its
// translation was too small to give a direction, and the frames the frontend calls pure
// rotations are mostly a car creeping into or out of a stop, where the last length is far
// too long (on the rendered stop-and-go drive: 0.25 m a frame for true steps of 0.004-0.08 m).
class PoseIntegrator {
 public:
  // Applies one frame. `motion.status == kFirstFrame` (re)starts the trajectory at identity.
  PoseUpdate Apply(const TwoViewMotion& motion, const ScaleResult& scale);

  const Rigid3d& world_from_cam() const { return world_from_cam_; }
  // The step applied by the last Apply.
  const Rigid3d& cur_from_prev() const { return cur_from_prev_; }
  // The length of the last step (metres).
  double step_length() const { return cur_from_prev_.translation().norm(); }
  // Whether a valid length has been applied since the first frame.
  bool has_scale() const { return has_scale_; }

 private:
  Rigid3d world_from_cam_ = Rigid3d::Identity();
  Rigid3d cur_from_prev_ = Rigid3d::Identity();
  Eigen::Matrix3d last_rotation_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d last_direction_ = Eigen::Vector3d::Zero();
  double last_length_ = 1.0;
  double last_motion_parallax_px_ = 0.0;  // of the last kOk motion
  bool has_scale_ = false;
};

}  // namespace roadscale
