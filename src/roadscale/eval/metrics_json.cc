#include "roadscale/eval/metrics_json.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace roadscale {
namespace {

using Json = nlohmann::ordered_json;

// The double whose shortest decimal form is the float nearest to `value`, so that the JSON
// shows the digits a single-precision result has, not the noise of its widening to double.
double AtFloatPrecision(double value) {
  char buffer[32];
  const std::to_chars_result result =
      std::to_chars(buffer, buffer + sizeof(buffer) - 1, static_cast<float>(value));
  *result.ptr = '\0';
  return std::strtod(buffer, nullptr);
}

Json KittiPercent(const std::optional<float>& t_err) {
  if (!t_err) return nullptr;
  return AtFloatPrecision(KittiTErrPercent(*t_err));
}

Json KittiDegPerMetre(const std::optional<float>& r_err) {
  if (!r_err) return nullptr;
  return AtFloatPrecision(KittiRErrDegPerMetre(*r_err));
}

Json OrNull(const std::optional<double>& value) {
  if (!value) return nullptr;
  return *value;
}

Json Length(float length_m) {
  if (std::floor(length_m) == length_m) return static_cast<int64_t>(length_m);
  return static_cast<double>(length_m);
}

}  // namespace

double KittiTErrPercent(float t_err) { return 100.0 * static_cast<double>(t_err); }

double KittiRErrDegPerMetre(float r_err) {
  return static_cast<double>(r_err) * (180.0 / 3.14159265358979323846);
}

nlohmann::ordered_json MetricsToJson(const TrajectoryEvaluation& evaluation) {
  const KittiOdometryResult& kitti = evaluation.kitti;
  const TrajectoryErrors& errors = evaluation.errors;

  Json per_length = Json::array();
  for (const KittiLengthResult& length : kitti.per_length) {
    Json entry;
    entry["length_m"] = Length(length.length_m);
    entry["n_segments"] = length.n_segments;
    entry["t_err_pct"] = KittiPercent(length.t_err);
    entry["r_err_deg_per_m"] = KittiDegPerMetre(length.r_err);
    per_length.push_back(entry);
  }

  Json json;
  json["frames"] = evaluation.frames;
  json["kitti"]["t_err_pct"] = KittiPercent(kitti.t_err);
  json["kitti"]["r_err_deg_per_m"] = KittiDegPerMetre(kitti.r_err);
  json["kitti"]["n_segments"] = kitti.n_segments();
  json["kitti"]["per_length"] = per_length;
  json["ate_m"]["none"] = errors.ate_none_m;
  json["ate_m"]["se3"] = errors.ate_se3_m;
  json["ate_m"]["sim3"] = OrNull(errors.ate_sim3_m);
  json["ate_m"]["sim3_scale"] = OrNull(errors.sim3_scale);
  json["rpe"]["trans_rmse_m"] = errors.rpe_trans_rmse_m;
  json["rpe"]["rot_rmse_deg"] = errors.rpe_rot_rmse_deg;
  json["length_ratio"] = OrNull(errors.length_ratio);
  json["final_drift_m"] = errors.final_drift_m;
  json["final_drift_pct"] = OrNull(errors.final_drift_pct);
  return json;
}

std::string FormatMetricsJson(const TrajectoryEvaluation& evaluation) {
  return MetricsToJson(evaluation).dump(2) + "\n";
}

}  // namespace roadscale
