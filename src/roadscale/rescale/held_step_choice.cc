#include "roadscale/rescale/held_step_choice.h"

#include <cmath>

#include "roadscale/util/median.h"

namespace roadscale {

HeldStepChoice::HeldStepChoice(const ScaleFilterOptions& filter) : speed_filter_(filter) {}

void HeldStepChoice::AddFixed(double ratio, double speed, bool previous_fixed) {
  if (!(ratio > 0.0) || !std::isfinite(ratio)) return;
  const bool has_speed = speed > 0.0 && std::isfinite(speed);
  if (has_speed) speed_filter_.Add(speed);
  if (previous_fixed && has_speed && last_ratio_ > 0.0 && last_speed_ > 0.0) {
    ratio_changes_.push_back(std::abs(std::log(ratio / last_ratio_)));
    speed_changes_.push_back(std::abs(std::log(speed / last_speed_)));
  }
  last_ratio_ = ratio;
  last_speed_ = has_speed ? speed : 0.0;
}

bool HeldStepChoice::HoldsSpeed() const {
  if (static_cast<int>(ratio_changes_.size()) < kMinComparisons) return false;
  return Median(speed_changes_) < Median(ratio_changes_);
}

}  // namespace roadscale
