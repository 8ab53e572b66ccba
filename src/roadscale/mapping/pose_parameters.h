#pragma once

#include <array>

#include "roadscale/geometry/rigid3.h"

namespace roadscale {

// A cam_from_world pose as Ceres optimises it: angle-axis rotation (3) then translation (3).
using PoseParameters = std::array<double, 6>;

PoseParameters ToPoseParameters(const Rigid3d& cam_from_world);
Rigid3d FromPoseParameters(const PoseParameters& parameters);

}  // namespace roadscale
