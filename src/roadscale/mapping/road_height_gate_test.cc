#include "roadscale/mapping/road_height_gate.h"

#include <gtest/gtest.h>

namespace roadscale {
namespace {

TEST(RoadHeightGate, AcceptsThePlaneOfTheMapAndRejectsOneAtEightTimesItsHeight) {
  const std::vector<double> window = {1.64, 1.66, 1.65, 1.63, 1.67, 1.65, 1.66, 1.64};
  EXPECT_TRUE(RoadHeightsAgree({1.55, 1.58, 1.52}, window, {}, 1.5));
  EXPECT_TRUE(RoadHeightsAgree({2.3, 2.4, 2.35}, window, {}, 1.5));  // 1.42 times: a drifted map
  // Highway seed 1, keyframe 164: six points on a plane at 13.3 map units.
  EXPECT_FALSE(RoadHeightsAgree({13.34, 13.47, 13.36, 13.34, 13.33, 13.36}, window, {}, 1.5));
  EXPECT_FALSE(RoadHeightsAgree({0.9, 1.0, 0.95}, window, {}, 1.5));  // below as well as above
  EXPECT_FALSE(RoadHeightsAgree({}, window, {}, 1.5));
}

TEST(RoadHeightGate, AgreesWhenTheWindowHasTooFewRoadLandmarksToCompare) {
  EXPECT_TRUE(RoadHeightsAgree({13.3, 13.4}, {1.65, 1.66}, {}, 1.5));
  EXPECT_TRUE(RoadHeightsAgree({13.3}, {}, {}, 1.5));
}

// Highway seed 2 with the alignment limited to the car's lane, keyframe 219: seven points on
// a plane at five times the road's height in a window whose only road measurements were
// three road alignments; they pulled the map to a fifth of its scale for 60 frames.
TEST(RoadHeightGate, ComparesWithTheRoadAlignmentsWhenTheWindowHasTooFewRoadLandmarks) {
  const std::vector<double> alignments = {0.33, 0.34, 0.33};
  EXPECT_FALSE(RoadHeightsAgree({1.7, 1.8, 1.75, 1.72}, {1.7, 1.8}, alignments, 1.5));
  EXPECT_TRUE(RoadHeightsAgree({0.35, 0.36, 0.34}, {1.7, 1.8}, alignments, 1.5));
  // Three road landmarks outrank the alignments.
  EXPECT_TRUE(RoadHeightsAgree({1.7, 1.8}, {1.7, 1.8, 1.75}, alignments, 1.5));
}

}  // namespace
}  // namespace roadscale
