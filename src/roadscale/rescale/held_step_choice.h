#pragma once

#include <vector>

#include "roadscale/scale/scale_filter.h"

namespace roadscale {

// What a step without a road fix of its own keeps: the last metres per VO unit (right for a
// VO whose step lengths are right up to a slowly drifting scale, like Wang et al.'s) or the
// car's last speed (right for a VO whose step lengths jump from step to step, like
// LibVISO2-M's, which made its own steps twice too long in KITTI 07's second turn while the
// road was out of view: held at the ratio they came out 1.5-1.9 times the truth). The road
// fixes tell which: whichever of the two changes less from one fixed step to the next.
class HeldStepChoice {
 public:
  explicit HeldStepChoice(const ScaleFilterOptions& filter = {});

  // A step with its own road fix: its ratio (metres per VO unit) and metric speed (m/s; not
  // positive when the step's time is unknown). `previous_fixed`: whether the step before it
  // had its own fix too (only consecutive fixed steps compare).
  void AddFixed(double ratio, double speed, bool previous_fixed);

  // True once at least kMinComparisons pairs of consecutive fixed steps have shown the speed
  // changing less than the ratio (medians of the absolute change of their logarithms).
  bool HoldsSpeed() const;
  // The filtered speed of the fixed steps (the scale filter of eqs. 14-16); NaN before any.
  double speed() const { return speed_filter_.Current(); }

  static constexpr int kMinComparisons = 5;

 private:
  ScaleFilter speed_filter_;
  double last_ratio_ = 0.0;
  double last_speed_ = 0.0;
  std::vector<double> ratio_changes_;
  std::vector<double> speed_changes_;
};

}  // namespace roadscale
