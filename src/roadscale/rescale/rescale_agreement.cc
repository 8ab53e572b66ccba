#include "roadscale/rescale/rescale_agreement.h"

#include <algorithm>
#include <cmath>

namespace roadscale {
namespace {

// The median absolute deviation scaled to a normal distribution's standard deviation.
double RobustDeviation(std::vector<double> values) {
  const auto median_of = [](std::vector<double>* v) {
    const auto middle = v->begin() + static_cast<std::ptrdiff_t>(v->size() / 2);
    std::nth_element(v->begin(), middle, v->end());
    return *middle;
  };
  const double median = median_of(&values);
  for (double& value : values) value = std::abs(value - median);
  return 1.4826 * median_of(&values);
}

}  // namespace

double InputAgreement::InputStepError() const {
  return std::sqrt(std::max(0.0, step_spread * step_spread - fix_noise * fix_noise));
}

std::optional<InputAgreement> MeasureInputAgreement(const std::vector<RescaledPose>& steps) {
  std::vector<double> fix_differences;
  std::vector<double> ratio_changes;
  const RescaledPose* previous = nullptr;
  for (const RescaledPose& step : steps) {
    const bool own =
        step.status == RescaleStatus::kOk && step.road_steps == 1 && std::isfinite(step.raw_ratio);
    if (own && std::isfinite(step.points_ratio) && std::isfinite(step.alignment_ratio)) {
      fix_differences.push_back(std::log(step.points_ratio / step.alignment_ratio));
    }
    if (own && previous != nullptr && previous->pose + 1 == step.pose) {
      ratio_changes.push_back(std::log(step.raw_ratio / previous->raw_ratio));
    }
    previous = own ? &step : nullptr;
  }
  const int fix_pairs = static_cast<int>(fix_differences.size());
  const int step_pairs = static_cast<int>(ratio_changes.size());
  if (fix_pairs < kMinAgreementSteps || step_pairs < kMinAgreementSteps) return std::nullopt;
  InputAgreement agreement;
  agreement.fix_pairs = fix_pairs;
  agreement.step_pairs = step_pairs;
  // Two fixes with independent errors of deviation s: their log difference has s * sqrt(2),
  // their geometric mean (the step's own ratio) s / sqrt(2).
  agreement.fix_noise = RobustDeviation(std::move(fix_differences)) / 2.0;
  // The change between consecutive steps holds two steps' errors (a slow drift of the VO's
  // scale adds little from one step to the next).
  agreement.step_spread = RobustDeviation(std::move(ratio_changes)) / std::sqrt(2.0);
  return agreement;
}

}  // namespace roadscale
