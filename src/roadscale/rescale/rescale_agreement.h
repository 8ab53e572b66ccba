#pragma once

#include <optional>
#include <vector>

#include "roadscale/rescale/trajectory_rescaler.h"

namespace roadscale {

// How another VO's step lengths compare with the road's, over a rescaled trajectory. A step's
// own ratio (metres per VO unit) varies from step to step with the road fix's own error and
// with the VO's step-length error; the fix's error alone shows in the disagreement of the
// step's two fixes (the road points' plane and the road alignment). When the ratios vary no
// more than the fixes' noise explains, the VO's lengths are as good as the road's, and taking
// each step's own ratio (the rescaler's default) only adds the fixes' noise to a good input:
// `rescale --smooth-ratio` keeps its lengths up to a slowly varying scale instead. On the
// shared KITTI frames: the ground truth and its destroyed-scale copy 0.63-0.93 times the
// fixes' noise, Wang et al.'s trajectories 1.33-1.46 times, LibVISO2-M's 2.4-4.9 times
// (docs/benchmark-history.md, "Does the input agree with the road?").
struct InputAgreement {
  int fix_pairs = 0;   // steps with both fixes
  int step_pairs = 0;  // pairs of consecutive steps with their own ratio
  double fix_noise =
      0.0;  // a step's own log ratio's error: robust sd of log(points / alignment) / 2
  double step_spread =
      0.0;  // robust sd of the change of log ratio between consecutive steps / sqrt(2)

  // The ratios vary no more than the fixes' noise explains (within kAgreementMargin: the
  // sampling error of two robust deviations from a few dozen steps each).
  bool InputAsGoodAsTheRoad() const { return step_spread <= kAgreementMargin * fix_noise; }
  // The input's own step-length error (log units) the spread implies beyond the fixes' noise.
  double InputStepError() const;

  static constexpr double kAgreementMargin = 1.2;
};

// Needs at least kMinAgreementSteps steps with both fixes and as many pairs of consecutive
// steps with their own ratio; std::nullopt otherwise.
inline constexpr int kMinAgreementSteps = 20;
std::optional<InputAgreement> MeasureInputAgreement(const std::vector<RescaledPose>& steps);

}  // namespace roadscale
