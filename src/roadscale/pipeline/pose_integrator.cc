#include "roadscale/pipeline/pose_integrator.h"

#include <algorithm>

namespace roadscale {

std::string PoseUpdateName(PoseUpdate update) {
  switch (update) {
    case PoseUpdate::kFirst:
      return "first";
    case PoseUpdate::kMotion:
      return "motion";
    case PoseUpdate::kKept:
      return "kept";
    case PoseUpdate::kRotationOnly:
      return "rotation_only";
    case PoseUpdate::kConstantVelocity:
      return "constant_velocity";
  }
  return "unknown";
}

double ParallaxScaledLength(double reference_length, double parallax_px,
                            double reference_parallax_px) {
  if (!(parallax_px > 0.0) || !(reference_parallax_px > 0.0)) return reference_length;
  return reference_length * parallax_px / reference_parallax_px;
}

PoseUpdate PoseIntegrator::Apply(const TwoViewMotion& motion, const ScaleResult& scale) {
  if (motion.status == MotionStatus::kFirstFrame) {
    *this = PoseIntegrator();
    return PoseUpdate::kFirst;
  }
  if (scale.valid) {
    last_length_ = scale.step_length_m;
    has_scale_ = true;
  }

  PoseUpdate update;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double length = last_length_;
  switch (motion.status) {
    case MotionStatus::kOk:
      update = PoseUpdate::kMotion;
      rotation = motion.rotation;
      direction = motion.direction;
      last_rotation_ = rotation;
      last_direction_ = direction;
      last_motion_parallax_px_ = motion.parallax_px;
      break;
    case MotionStatus::kStationary:
      update = PoseUpdate::kKept;
      break;
    case MotionStatus::kPureRotation:
      update = PoseUpdate::kRotationOnly;
      rotation = motion.rotation;
      direction = last_direction_;
      if (!scale.valid) {
        length = std::min(last_length_, ParallaxScaledLength(last_length_, motion.parallax_px,
                                                             last_motion_parallax_px_));
      }
      break;
    default:
      update = PoseUpdate::kConstantVelocity;
      rotation = last_rotation_;
      direction = last_direction_;
      break;
  }
  cur_from_prev_ = MakeRigid3d(rotation, direction * length);
  world_from_cam_ = world_from_cam_ * cur_from_prev_.inverse();
  return update;
}

}  // namespace roadscale
