#include "roadscale/eval/report_table.h"

#include "roadscale/eval/metrics_json.h"
#include "roadscale/util/string_printf.h"

namespace roadscale {
namespace {

std::string NoSegmentFits(float length_m, float path_length_m) {
  return StringPrintf("no segment of %g m fits a %.1f m trajectory", static_cast<double>(length_m),
                      static_cast<double>(path_length_m));
}

void AppendKitti(const KittiOdometryResult& kitti, std::string& out) {
  out += "KITTI odometry metric (devkit definition and precision)\n";
  if (!kitti.t_err || !kitti.r_err) {
    const float shortest = kitti.per_length.empty() ? 0.0f : kitti.per_length.front().length_m;
    out += "  undefined: " + NoSegmentFits(shortest, kitti.gt_path_length_m) + "\n";
    return;
  }
  out +=
      StringPrintf("  t_err %.4f %%   r_err %.6f deg/m   (%d segments, ground-truth path %.1f m)\n",
                   KittiTErrPercent(*kitti.t_err), KittiRErrDegPerMetre(*kitti.r_err),
                   kitti.n_segments(), static_cast<double>(kitti.gt_path_length_m));
  out += "  length [m]  segments  t_err [%]  r_err [deg/m]\n";
  for (const KittiLengthResult& length : kitti.per_length) {
    if (length.t_err && length.r_err) {
      out += StringPrintf("  %10g  %8d  %9.4f  %13.6f\n", static_cast<double>(length.length_m),
                          length.n_segments, KittiTErrPercent(*length.t_err),
                          KittiRErrDegPerMetre(*length.r_err));
    } else {
      out += StringPrintf("  %10g  %8d  %s\n", static_cast<double>(length.length_m), 0,
                          NoSegmentFits(length.length_m, kitti.gt_path_length_m).c_str());
    }
  }
}

void AppendErrors(const TrajectoryErrors& errors, std::string& out) {
  out += "Absolute trajectory error (position RMSE, estimate aligned onto ground truth)\n";
  out += StringPrintf("  none %.4f m   se3 %.4f m   ", errors.ate_none_m, errors.ate_se3_m);
  if (errors.ate_sim3_m && errors.sim3_scale) {
    out += StringPrintf("sim3 %.4f m (scale %.6f)\n", *errors.ate_sim3_m, *errors.sim3_scale);
  } else {
    out += "sim3 undefined (the estimate does not move)\n";
  }
  out += "Relative pose error (consecutive frames, RMSE)\n";
  out += StringPrintf("  translation %.5f m   rotation %.5f deg\n", errors.rpe_trans_rmse_m,
                      errors.rpe_rot_rmse_deg);
  out += StringPrintf("Path length: ground truth %.3f m, estimate %.3f m", errors.gt_path_length_m,
                      errors.est_path_length_m);
  out += errors.length_ratio ? StringPrintf(" (est/gt %.6f)\n", *errors.length_ratio)
                             : std::string(" (ratio undefined: the ground truth does not move)\n");
  out += StringPrintf("Final drift: %.4f m", errors.final_drift_m);
  out += errors.final_drift_pct
             ? StringPrintf(" (%.4f %% of the ground-truth path)\n", *errors.final_drift_pct)
             : std::string("\n");
}

}  // namespace

std::string FormatEvaluationTable(const TrajectoryEvaluation& evaluation) {
  std::string out = StringPrintf("Frames evaluated: %zu\n", evaluation.frames);
  AppendKitti(evaluation.kitti, out);
  AppendErrors(evaluation.errors, out);
  return out;
}

}  // namespace roadscale
