#include "roadscale/mapping/steady_road_normal.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// The camera's down axis tilted forward by `pitch_deg` (the road's normal seen by a camera
// pitched against it, or a pair's travel that climbs or dips).
Eigen::Vector3d Tilted(double pitch_deg) {
  const double pitch = pitch_deg * M_PI / 180.0;
  return {0.0, std::cos(pitch), std::sin(pitch)};
}

TEST(SteadyRoadNormal, FollowsARoadWhoseGradeChangesByDegreesBetweenKeyframes) {
  SteadyRoadNormal normal(5.0);
  for (int step = 0; step < 10; ++step) {
    const Eigen::Vector3d pair = Tilted(-3.0 + 2.0 * step);
    EXPECT_TRUE(normal.Next(pair).isApprox(pair)) << "step " << step;
  }
}

// The real traffic drive, stopping: keyframes 44 -> 50 travelled 17 degrees down.
TEST(SteadyRoadNormal, KeepsTheLastNormalAgainstOneStoppingPairsTravel) {
  SteadyRoadNormal normal(5.0);
  EXPECT_TRUE(normal.Next(Tilted(-3.3)).isApprox(Tilted(-3.3)));
  EXPECT_TRUE(normal.Next(Tilted(-3.1)).isApprox(Tilted(-3.1)));
  EXPECT_TRUE(normal.Next(Tilted(14.0)).isApprox(Tilted(-3.1)));
  EXPECT_TRUE(normal.Next(Tilted(-2.9)).isApprox(Tilted(-2.9)));
}

// A wrong first normal must not hold the map: two pairs in a row that agree replace it.
TEST(SteadyRoadNormal, TakesTheNormalThatTwoPairsInARowAgreeOn) {
  SteadyRoadNormal normal(5.0);
  EXPECT_TRUE(normal.Next(Tilted(20.0)).isApprox(Tilted(20.0)));
  EXPECT_TRUE(normal.Next(Tilted(-3.0)).isApprox(Tilted(20.0)));
  EXPECT_TRUE(normal.Next(Tilted(-2.8)).isApprox(Tilted(-2.8)));
  EXPECT_TRUE(normal.Next(Tilted(-2.9)).isApprox(Tilted(-2.9)));
}

TEST(SteadyRoadNormal, RejectsATurnLimitOutsideZeroToNinetyDegrees) {
  EXPECT_THROW(SteadyRoadNormal(0.0), Error);
  EXPECT_NO_THROW(SteadyRoadNormal(90.0));
  EXPECT_THROW(SteadyRoadNormal(90.5), Error);
  EXPECT_THROW(SteadyRoadNormal(std::nan("")), Error);
}

}  // namespace
}  // namespace roadscale
