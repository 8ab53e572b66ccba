#include "roadscale/eval/trajectory_evaluation.h"

#include <cmath>
#include <iomanip>

#include <gtest/gtest.h>

#include "roadscale/io/trajectory_io.h"
#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/test_trajectories.h"

namespace roadscale {
namespace {

void ExpectRelativelyNear(double actual, double expected, const char* what) {
  EXPECT_NEAR(actual, expected, 1e-6 * std::abs(expected))
      << what << ": actual " << std::setprecision(17) << actual;
}

TEST(TrajectoryEvaluation, GroundTruthAgainstItselfIsAllZeros) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(1200, 1.0);
  const TrajectoryEvaluation evaluation = EvaluateTrajectory(gt, gt);
  EXPECT_EQ(evaluation.frames, 1200u);
  ASSERT_TRUE(evaluation.kitti.t_err && evaluation.kitti.r_err);
  EXPECT_GT(evaluation.kitti.n_segments(), 0);
  // The error poses' diagonals, computed in double, round to exactly 1 in float; their
  // translations are rounding noise of the double inverses.
  EXPECT_LT(*evaluation.kitti.t_err, 1e-12f);
  EXPECT_EQ(*evaluation.kitti.r_err, 0.0f);
  EXPECT_EQ(evaluation.errors.ate_none_m, 0.0);
  EXPECT_NEAR(evaluation.errors.ate_se3_m, 0.0, 1e-9);
  EXPECT_NEAR(*evaluation.errors.ate_sim3_m, 0.0, 1e-9);
  EXPECT_NEAR(evaluation.errors.rpe_trans_rmse_m, 0.0, 1e-12);
  EXPECT_EQ(evaluation.errors.final_drift_m, 0.0);
}

// Sequence 05 (2761 poses, 2205 m) against an estimate with seeded per-frame noise (up to
// 1 % on each step's length, up to 1 mrad about each axis) and a slow scale drift (+4 % by
// the end).
// The KITTI values are the devkit's: its evaluate_odometry.cpp error computation with its
// Matrix class (double, Gauss-Jordan inverse with full pivoting), transcribed line by line
// into a throwaway program and run on these poses written with 17 digits. An implementation
// with float matrix arithmetic is 2.7e-5 relative off in r_err, beyond the 1e-6 here.
TEST(TrajectoryEvaluation, Kitti05RegressionValues) {
  ROADSCALE_REQUIRE_SHARED("kitti/poses/05.txt");
  const std::vector<Rigid3d> gt =
      ReadKittiTrajectory(testing::SharedPath("kitti/poses/05.txt").string()).world_from_cam;
  ASSERT_EQ(gt.size(), 2761u);
  const std::vector<Rigid3d> est = testing::PerturbedEstimate(gt, 5, 0.04, 0.01, 1e-3);
  const TrajectoryEvaluation evaluation = EvaluateTrajectory(gt, est);
  const KittiOdometryResult& kitti = evaluation.kitti;
  const TrajectoryErrors& errors = evaluation.errors;

  EXPECT_EQ(kitti.n_segments(), 1806);
  ExpectRelativelyNear(*kitti.t_err, 0.0165383872, "t_err");
  ExpectRelativelyNear(*kitti.r_err, 6.77464486e-05, "r_err");
  ExpectRelativelyNear(kitti.gt_path_length_m, 2205.57837, "gt_path_length_m");
  struct Expected {
    int n_segments;
    double t_err;
    double r_err;
  };
  const Expected per_length[8] = {
      {267, 0.0201781671, 0.000105147708}, {258, 0.020022219, 8.20708519e-05},
      {248, 0.0192482322, 7.31711625e-05}, {227, 0.016939126, 6.57347118e-05},
      {218, 0.0158415288, 5.95701458e-05}, {205, 0.0137974219, 5.20853282e-05},
      {196, 0.0122086396, 4.57090173e-05}, {187, 0.0108099682, 3.96279393e-05}};
  ASSERT_EQ(kitti.per_length.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    const KittiLengthResult& length = kitti.per_length[k];
    EXPECT_EQ(length.length_m, 100.0f * (k + 1));
    EXPECT_EQ(length.n_segments, per_length[k].n_segments) << length.length_m;
    ExpectRelativelyNear(*length.t_err, per_length[k].t_err, "per-length t_err");
    ExpectRelativelyNear(*length.r_err, per_length[k].r_err, "per-length r_err");
  }

  ExpectRelativelyNear(errors.ate_none_m, 9.6064526663459073, "ate_none_m");
  ExpectRelativelyNear(errors.ate_se3_m, 5.6617871626287162, "ate_se3_m");
  ExpectRelativelyNear(*errors.ate_sim3_m, 3.5910675070923204, "ate_sim3_m");
  ExpectRelativelyNear(*errors.sim3_scale, 0.97355173853564125, "sim3_scale");
  ExpectRelativelyNear(errors.rpe_trans_rmse_m, 0.02203103966801475, "rpe_trans_rmse_m");
  ExpectRelativelyNear(errors.rpe_rot_rmse_deg, 0.056870040003392817, "rpe_rot_rmse_deg");
  ExpectRelativelyNear(*errors.length_ratio, 1.0209431429309541, "length_ratio");
  ExpectRelativelyNear(errors.final_drift_m, 20.833737531178656, "final_drift_m");
  ExpectRelativelyNear(*errors.final_drift_pct, 0.94459405442218092, "final_drift_pct");
}

}  // namespace
}  // namespace roadscale
