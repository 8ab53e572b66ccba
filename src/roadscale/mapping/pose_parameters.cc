#include "roadscale/mapping/pose_parameters.h"

#include <ceres/rotation.h>

namespace roadscale {

PoseParameters ToPoseParameters(const Rigid3d& cam_from_world) {
  PoseParameters parameters;
  // Ceres' rotation helpers take column-major matrices, as Eigen stores them.
  const Eigen::Matrix3d rotation = cam_from_world.linear();
  ceres::RotationMatrixToAngleAxis(rotation.data(), parameters.data());
  for (int i = 0; i < 3; ++i) parameters[3 + i] = cam_from_world.translation()[i];
  return parameters;
}

Rigid3d FromPoseParameters(const PoseParameters& parameters) {
  Eigen::Matrix3d rotation;
  ceres::AngleAxisToRotationMatrix(parameters.data(), rotation.data());
  return MakeRigid3d(rotation, Eigen::Vector3d(parameters[3], parameters[4], parameters[5]));
}

}  // namespace roadscale
