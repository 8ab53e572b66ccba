#include "roadscale/eval/pose_pairing.h"

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

Trajectory Line(int poses, double first_time, bool with_times) {
  Trajectory trajectory;
  for (int i = 0; i < poses; ++i) {
    trajectory.world_from_cam.push_back(
        MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i)));
    if (with_times) trajectory.timestamps.push_back(first_time + 0.1 * i);
  }
  return trajectory;
}

TEST(PosePairing, PairsByIndexWithoutTimestamps) {
  const PosePairs pairs = PairPoses(Line(5, 0, false), Line(5, 0, true), "gt.txt", "est.txt");
  EXPECT_FALSE(pairs.by_time);
  EXPECT_EQ(pairs.size(), 5u);
}

TEST(PosePairing, CountsMustMatchWithoutTimestamps) {
  try {
    PairPoses(Line(5, 0, false), Line(4, 0, false), "gt.txt", "est.txt");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("est.txt has 4 poses but gt.txt has 5"), std::string::npos)
        << e.what();
  }
}

TEST(PosePairing, AssociatesByTimeWhenBothHaveTimestamps) {
  // The estimate starts 3 frames later (0.3 s) with a 2 ms clock offset.
  const Trajectory gt = Line(10, 0.0, true);
  Trajectory est = Line(5, 0.302, true);
  const PosePairs pairs = PairPoses(gt, est, "gt.txt", "est.txt");
  EXPECT_TRUE(pairs.by_time);
  ASSERT_EQ(pairs.size(), 5u);
  EXPECT_EQ(pairs.gt_world_from_cam[0].translation().z(), 3.0);
  EXPECT_EQ(pairs.est_world_from_cam[0].translation().z(), 0.0);
  EXPECT_EQ(pairs.gt_world_from_cam[4].translation().z(), 7.0);
}

TEST(PosePairing, TooFewTimeMatchesIsAnError) {
  const Trajectory gt = Line(10, 0.0, true);
  const Trajectory est = Line(10, 100.0, true);
  EXPECT_THROW(PairPoses(gt, est, "gt.txt", "est.txt"), Error);
}

TEST(PosePairing, NeedsTwoPoses) {
  EXPECT_THROW(PairPoses(Line(1, 0, false), Line(1, 0, false), "gt.txt", "est.txt"), Error);
}

}  // namespace
}  // namespace roadscale
