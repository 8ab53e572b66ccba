#pragma once

#include <string>

#include "roadscale/eval/trajectory_evaluation.h"

namespace roadscale {

// The readable report `roadscale eval` prints: the KITTI metric (pooled and per length,
// saying which lengths fit), ATE, RPE, path lengths and final drift. Several lines, each
// ending in a newline.
std::string FormatEvaluationTable(const TrajectoryEvaluation& evaluation);

}  // namespace roadscale
