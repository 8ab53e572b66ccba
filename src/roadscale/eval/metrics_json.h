#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "roadscale/eval/trajectory_evaluation.h"

namespace roadscale {

// The JSON that `roadscale eval --json` prints; later tooling depends on exactly this shape
// (keys in this order):
//   {"frames": N,
//    "kitti": {"t_err_pct": .., "r_err_deg_per_m": .., "n_segments": ..,
//              "per_length": [{"length_m": 100, "n_segments": .., "t_err_pct": ..,
//                              "r_err_deg_per_m": ..}, ...]},
//    "ate_m": {"none": .., "se3": .., "sim3": .., "sim3_scale": ..},
//    "rpe": {"trans_rmse_m": .., "rot_rmse_deg": ..},
//    "length_ratio": .., "final_drift_m": .., "final_drift_pct": ..}
// KITTI values are null when no segment fits (pooled) or none of that length fits (per
// length; every length of the metric is listed, with its n_segments). They are computed in
// single precision and written with a float's shortest round-trip digits. sim3 and
// sim3_scale are null when the estimate does not move; length_ratio and final_drift_pct
// when the ground truth does not move.
nlohmann::ordered_json MetricsToJson(const TrajectoryEvaluation& evaluation);

// MetricsToJson, indented by 2, with a final newline.
std::string FormatMetricsJson(const TrajectoryEvaluation& evaluation);

// A KITTI value in the report's units: t_err ratio -> %, r_err rad/m -> deg/m.
double KittiTErrPercent(float t_err);
double KittiRErrDegPerMetre(float r_err);

}  // namespace roadscale
