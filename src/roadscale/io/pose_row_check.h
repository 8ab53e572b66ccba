#pragma once

#include <string>

#include <Eigen/Core>

namespace roadscale {

// A trajectory file's pose must be a rigid transform: every consumer (the KITTI metric's
// inverses, ATE's alignment, rescale's step directions) silently turns anything else into
// NaN, inf or a "stationary" step. Rows are written with limited digits (KITTI's ground truth
// has 6-9 significant digits), so the rotation is checked within kRotationTolerance: max
// |R^T R - I| below it and det(R) > 0. That accepts rows rounded to 3 decimals and rejects a
// zero, scaled (by 1 % or more), sheared or mirrored 3x3 block.
inline constexpr double kRotationTolerance = 1e-2;

// Positions beyond this (fifteen Earth radii; ECEF coordinates are within one) are not a
// vehicle's: a unit or format mistake. It also keeps the devkit metric's single-precision
// path distances finite.
inline constexpr double kMaxTranslationM = 1e8;

// Throws Error naming `path` and `line` when `rotation` is not a rotation or `translation`
// is not finite or beyond kMaxTranslationM.
void CheckPoseRow(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                  const std::string& path, int line);

}  // namespace roadscale
