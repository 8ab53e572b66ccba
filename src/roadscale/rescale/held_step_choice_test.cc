#include "roadscale/rescale/held_step_choice.h"

#include <cmath>

#include <gtest/gtest.h>

namespace roadscale {
namespace {

// A car at a steady 10 m/s seen by a VO whose step lengths jump by a third from step to
// step: each fixed step's ratio (metres per VO unit) jumps with them, its speed does not.
TEST(HeldStepChoice, HoldsTheSpeedForAVoWhoseStepLengthsJump) {
  HeldStepChoice choice;
  for (int step = 0; step < 8; ++step) {
    const double vo_length = step % 2 == 0 ? 0.75 : 1.0;
    choice.AddFixed(/*ratio=*/1.0 / vo_length, /*speed=*/10.0, /*previous_fixed=*/step > 0);
  }
  EXPECT_TRUE(choice.HoldsSpeed());
  EXPECT_DOUBLE_EQ(choice.speed(), 10.0);
}

// A VO whose lengths are right up to a slowly drifting scale, on a car that speeds up by 10 %
// a step: the ratio is the steadier of the two.
TEST(HeldStepChoice, HoldsTheRatioForAVoWithASteadyScale) {
  HeldStepChoice choice;
  double speed = 5.0;
  for (int step = 0; step < 8; ++step) {
    choice.AddFixed(/*ratio=*/2.0 * (1.0 + 0.005 * step), speed, step > 0);
    speed *= 1.1;
  }
  EXPECT_FALSE(choice.HoldsSpeed());
}

// Only consecutive fixed steps compare, and a handful of them must have: before that the
// ratio is held, as the rescaler always did.
TEST(HeldStepChoice, ComparesOnlyConsecutiveFixedStepsAndNeedsEnoughOfThem) {
  HeldStepChoice choice;
  for (int step = 0; step < 20; ++step) {
    choice.AddFixed(step % 2 == 0 ? 1.0 : 1.5, 10.0, /*previous_fixed=*/false);
  }
  EXPECT_FALSE(choice.HoldsSpeed());
  for (int step = 0; step < HeldStepChoice::kMinComparisons; ++step) {
    EXPECT_FALSE(choice.HoldsSpeed()) << step;
    choice.AddFixed(step % 2 == 0 ? 1.0 : 1.5, 10.0, /*previous_fixed=*/true);
  }
  EXPECT_TRUE(choice.HoldsSpeed());
}

// Steps without a time (speed <= 0) or with an unusable ratio neither compare nor move the
// speed.
TEST(HeldStepChoice, IgnoresStepsWithoutATimeOrARatio) {
  HeldStepChoice choice;
  EXPECT_TRUE(std::isnan(choice.speed()));
  for (int step = 0; step < 10; ++step) {
    choice.AddFixed(step % 2 == 0 ? 1.0 : 1.5, /*speed=*/0.0, true);
    choice.AddFixed(std::nan(""), 10.0, true);
  }
  EXPECT_FALSE(choice.HoldsSpeed());
  EXPECT_TRUE(std::isnan(choice.speed()));
}

}  // namespace
}  // namespace roadscale
