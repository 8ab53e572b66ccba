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

// [v]x: the matrix with [v]x u = v x u.
Eigen::Matrix3d SkewMatrix(const Eigen::Vector3d& v);

// The rotation by |omega| radians about omega (the exponential map of so(3)).
Eigen::Matrix3d ExpSo3(const Eigen::Vector3d& omega);

}  // namespace roadscale
