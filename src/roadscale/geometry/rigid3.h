#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace roadscale {

// A rigid transform. Names say which frame it maps from and to: `world_from_cam` maps
// camera coordinates to world coordinates, so compositions read right to left
// (world_from_cur = world_from_prev * prev_from_cur).
using Rigid3d = Eigen::Isometry3d;

Rigid3d MakeRigid3d(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation);

// Rotation angle of R in radians, in [0, pi], accurate also for tiny angles.
double RotationAngle(const Eigen::Matrix3d& rotation);

// The nearest rotation matrix (by SVD) to a matrix read from a file with limited digits.
Eigen::Matrix3d NearestRotation(const Eigen::Matrix3d& matrix);

}  // namespace roadscale
