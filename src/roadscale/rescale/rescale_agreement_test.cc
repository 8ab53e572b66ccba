#include "roadscale/rescale/rescale_agreement.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/util/random.h"

namespace roadscale {
namespace {

// Steps of a VO whose step lengths are off by `input_error` (log sd, white) under a slowly
// drifting scale, each measured by two road fixes with independent errors of `fix_error`.
std::vector<RescaledPose> Steps(double input_error, double fix_error, int count, uint64_t seed) {
  Rng rng(seed);
  std::vector<RescaledPose> steps;
  for (int k = 1; k <= count; ++k) {
    const double true_ratio = 0.3 * std::exp(0.002 * k + input_error * rng.Normal());
    RescaledPose step;
    step.pose = static_cast<size_t>(k);
    step.status = RescaleStatus::kOk;
    step.road_steps = 1;
    step.points_ratio = true_ratio * std::exp(fix_error * rng.Normal());
    step.alignment_ratio = true_ratio * std::exp(fix_error * rng.Normal());
    step.raw_ratio = std::sqrt(step.points_ratio * step.alignment_ratio);
    steps.push_back(step);
  }
  return steps;
}

TEST(InputAgreement, AnExactInputVariesOnlyWithTheFixesNoise) {
  const std::optional<InputAgreement> agreement = MeasureInputAgreement(Steps(0.0, 0.03, 300, 1));
  ASSERT_TRUE(agreement.has_value());
  // Each fix 3 %: their geometric mean 3 % / sqrt(2).
  EXPECT_NEAR(agreement->fix_noise, 0.03 / std::sqrt(2.0), 0.004);
  EXPECT_NEAR(agreement->step_spread, agreement->fix_noise, 0.004);
  EXPECT_TRUE(agreement->InputAsGoodAsTheRoad());
}

TEST(InputAgreement, AnInputWithStepErrorsVariesMore) {
  const std::optional<InputAgreement> agreement = MeasureInputAgreement(Steps(0.06, 0.03, 300, 2));
  ASSERT_TRUE(agreement.has_value());
  EXPECT_FALSE(agreement->InputAsGoodAsTheRoad());
  EXPECT_NEAR(agreement->InputStepError(), 0.06, 0.012);
}

TEST(InputAgreement, HeldStepsBreakTheChainAndTooFewStepsGiveNoVerdict) {
  std::vector<RescaledPose> steps = Steps(0.0, 0.03, 40, 3);
  EXPECT_TRUE(MeasureInputAgreement(steps).has_value());
  // Every third step held: its neighbours are not consecutive own ratios.
  for (size_t k = 0; k < steps.size(); k += 3) {
    steps[k].status = RescaleStatus::kHeld;
    steps[k].raw_ratio = std::nan("");
  }
  const std::optional<InputAgreement> fewer = MeasureInputAgreement(steps);
  EXPECT_FALSE(fewer.has_value());
  EXPECT_FALSE(MeasureInputAgreement(Steps(0.0, 0.03, kMinAgreementSteps, 4)).has_value());
}

TEST(InputAgreement, StepsMeasuredOverASpanAreNotTheirOwnRatios) {
  std::vector<RescaledPose> steps = Steps(0.0, 0.03, 40, 3);
  // Every third step fixed over a span of poses: a ratio, but not the step's own.
  for (size_t k = 0; k < steps.size(); k += 3) steps[k].road_steps = 3;
  EXPECT_FALSE(MeasureInputAgreement(steps).has_value());
}

}  // namespace
}  // namespace roadscale
