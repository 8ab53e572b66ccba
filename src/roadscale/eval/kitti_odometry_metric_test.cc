#include "roadscale/eval/kitti_odometry_metric.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/io/trajectory_io.h"
#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/test_trajectories.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// Poses with identity rotation at (0, 0, z) for z = 0, 1, ..., frames - 1: 1 m steps.
// An independent double-precision reading of the devkit's definition, written differently
// on purpose: rigid inverses instead of general ones, the error's translation length taken
// before rotating it (rotations keep lengths), the angle from Eigen's AngleAxis, segment
// ends found by walking forward on differences of cumulative distances, double sums.
struct ReferenceMetric {
  double t_err = 0;
  double r_err = 0;
  int n_segments = 0;
  std::vector<double> per_length_t_err;
  std::vector<int> per_length_segments;
};

ReferenceMetric ReferenceKittiMetric(const std::vector<Rigid3d>& gt,
                                     const std::vector<Rigid3d>& est) {
  const size_t n = gt.size();
  std::vector<double> cumulative(n, 0.0);
  for (size_t i = 1; i < n; ++i) {
    cumulative[i] = cumulative[i - 1] + (gt[i].translation() - gt[i - 1].translation()).norm();
  }
  ReferenceMetric reference;
  reference.per_length_t_err.assign(8, 0.0);
  reference.per_length_segments.assign(8, 0);
  for (size_t a = 0; a < n; a += 10) {
    for (int k = 0; k < 8; ++k) {
      const double length = 100.0 * (k + 1);
      size_t b = a;
      while (b < n && !(cumulative[b] - cumulative[a] > length)) ++b;
      if (b == n) continue;
      const Eigen::Matrix3d gt_rotation = gt[a].linear().transpose() * gt[b].linear();
      const Eigen::Vector3d gt_translation =
          gt[a].linear().transpose() * (gt[b].translation() - gt[a].translation());
      const Eigen::Matrix3d est_rotation = est[a].linear().transpose() * est[b].linear();
      const Eigen::Vector3d est_translation =
          est[a].linear().transpose() * (est[b].translation() - est[a].translation());
      const double t = (gt_translation - est_translation).norm() / length;
      const double r = Eigen::AngleAxisd(est_rotation.transpose() * gt_rotation).angle() / length;
      reference.t_err += t;
      reference.r_err += r;
      ++reference.n_segments;
      reference.per_length_t_err[k] += t;
      ++reference.per_length_segments[k];
    }
  }
  reference.t_err /= reference.n_segments;
  reference.r_err /= reference.n_segments;
  for (int k = 0; k < 8; ++k) {
    if (reference.per_length_segments[k] > 0) {
      reference.per_length_t_err[k] /= reference.per_length_segments[k];
    }
  }
  return reference;
}

void ExpectAgreesWithReference(const std::vector<Rigid3d>& gt, const std::vector<Rigid3d>& est,
                               double relative_tolerance) {
  const KittiOdometryResult result = EvaluateKittiOdometry(gt, est);
  const ReferenceMetric reference = ReferenceKittiMetric(gt, est);
  ASSERT_TRUE(result.t_err && result.r_err);
  // Single and double precision may end a few segments one frame apart, never more.
  EXPECT_NEAR(result.n_segments(), reference.n_segments, 2);
  EXPECT_NEAR(*result.t_err, reference.t_err, relative_tolerance * reference.t_err);
  EXPECT_NEAR(*result.r_err, reference.r_err, relative_tolerance * reference.r_err);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(result.per_length[k].n_segments > 0, reference.per_length_segments[k] > 0) << k;
    if (!result.per_length[k].t_err) continue;
    EXPECT_NEAR(*result.per_length[k].t_err, reference.per_length_t_err[k],
                2.0 * relative_tolerance * reference.per_length_t_err[k])
        << "length " << result.per_length[k].length_m;
  }
}

TEST(KittiOdometryMetric, HandBuiltThreeSegments) {
  // 131 poses 1 m apart along z: 100 m segments start at frames 0, 10 and 20 and end at
  // 101, 111 and 121 (frame 100 is exactly 100 m on, which does not exceed 100 m); a start
  // at 30 would need frame 131. No longer length fits.
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(131);
  std::vector<Rigid3d> est = gt;
  // Segment 0 -> 101: the estimate ends 3 m to the side: |t| = 3, t_err 0.03.
  est[101].translation() += Eigen::Vector3d(3, 0, 0);
  // Segment 10 -> 111: 4 m short: t_err 0.04.
  est[111].translation() += Eigen::Vector3d(0, 0, -4);
  // Segment 20 -> 121: off by (0, 4, 3) and turned by 0.3 rad about y. The error pose is
  // (R^T, R^T ((0,0,101) - (0,4,104))): |t| = 5, angle 0.3; t_err 0.05, r_err 0.003.
  est[121].translation() += Eigen::Vector3d(0, 4, 3);
  est[121].linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  // Frame 100 must not be a segment end: an error there would change the result.
  est[100].translation() += Eigen::Vector3d(50, 0, 0);

  const KittiOdometryResult result = EvaluateKittiOdometry(gt, est);
  ASSERT_EQ(result.n_segments(), 3);
  EXPECT_EQ(result.segments[0].first_frame, 0);
  EXPECT_EQ(result.segments[0].last_frame, 101);
  EXPECT_EQ(result.segments[1].first_frame, 10);
  EXPECT_EQ(result.segments[1].last_frame, 111);
  EXPECT_EQ(result.segments[2].first_frame, 20);
  EXPECT_EQ(result.segments[2].last_frame, 121);
  EXPECT_NEAR(result.segments[0].t_err, 0.03f, 1e-7);
  EXPECT_NEAR(result.segments[1].t_err, 0.04f, 1e-7);
  EXPECT_NEAR(result.segments[2].t_err, 0.05f, 1e-7);
  EXPECT_EQ(result.segments[0].r_err, 0.0f);
  EXPECT_NEAR(result.segments[2].r_err, 0.003f, 1e-8);
  // Pooled: (0.03 + 0.04 + 0.05) / 3 = 0.04 (4 %); r_err 0.3 rad / 300 m.
  ASSERT_TRUE(result.t_err && result.r_err);
  EXPECT_NEAR(*result.t_err, 0.04f, 1e-7);
  EXPECT_NEAR(*result.r_err, 0.001f, 1e-8);
  EXPECT_FLOAT_EQ(result.gt_path_length_m, 130.0f);

  ASSERT_EQ(result.per_length.size(), 8u);
  EXPECT_EQ(result.per_length[0].length_m, 100.0f);
  EXPECT_EQ(result.per_length[0].n_segments, 3);
  ASSERT_TRUE(result.per_length[0].t_err);
  EXPECT_NEAR(*result.per_length[0].t_err, 0.04f, 1e-7);
  for (size_t k = 1; k < 8; ++k) {
    EXPECT_EQ(result.per_length[k].n_segments, 0);
    EXPECT_FALSE(result.per_length[k].t_err);
    EXPECT_FALSE(result.per_length[k].r_err);
  }
}

TEST(KittiOdometryMetric, PerLengthMeansAndPooledMeanOverAllLengths) {
  // 221 poses 1 m apart: 100 m segments start at 0..110 (12), 200 m at 0 and 10 (2).
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(221);
  std::vector<Rigid3d> est = gt;
  // Every frame 10 % further along than the truth: every segment's error is 10 % of the
  // true distance it covers, i.e. 0.1 * 101 / 100 for 100 m and 0.1 * 201 / 200 for 200 m.
  for (int i = 0; i < 221; ++i) est[i].translation().z() = 1.1 * i;
  const KittiOdometryResult result = EvaluateKittiOdometry(gt, est);
  EXPECT_EQ(result.per_length[0].n_segments, 12);
  EXPECT_EQ(result.per_length[1].n_segments, 2);
  EXPECT_EQ(result.n_segments(), 14);
  EXPECT_NEAR(*result.per_length[0].t_err, 0.101, 1e-6);
  EXPECT_NEAR(*result.per_length[1].t_err, 0.1005, 1e-6);
  EXPECT_NEAR(*result.t_err, (12 * 0.101 + 2 * 0.1005) / 14, 1e-6);
  EXPECT_EQ(*result.r_err, 0.0f);
  // Starts every 10 frames, in the devkit's order (start outer, length inner).
  EXPECT_EQ(result.segments[0].first_frame, 0);
  EXPECT_EQ(result.segments[0].length_m, 100.0f);
  EXPECT_EQ(result.segments[1].first_frame, 0);
  EXPECT_EQ(result.segments[1].length_m, 200.0f);
  EXPECT_EQ(result.segments[2].first_frame, 10);
  EXPECT_EQ(result.segments.back().first_frame, 110);
}

TEST(KittiOdometryMetric, SegmentEndsFollowSinglePrecisionDistances) {
  // Frame 1 lies 100.000001 m from frame 0. In double that exceeds 100 m and would end the
  // segment there; rounded to float it is exactly 100 m, which does not, so the devkit (and
  // this metric) end it at frame 2, where the estimate is 5 m off.
  std::vector<Rigid3d> gt(3, Rigid3d::Identity());
  gt[1].translation() = Eigen::Vector3d(0, 0, 100.000001);
  gt[2].translation() = Eigen::Vector3d(0, 0, 101);
  std::vector<Rigid3d> est = gt;
  est[2].translation().x() = 5.0;
  ASSERT_EQ(static_cast<float>(100.000001), 100.0f);
  const KittiOdometryResult result = EvaluateKittiOdometry(gt, est);
  ASSERT_EQ(result.n_segments(), 1);
  EXPECT_EQ(result.segments[0].last_frame, 2);
  EXPECT_NEAR(*result.t_err, 0.05f, 1e-7);
}

TEST(KittiOdometryMetric, IdentityEstimateHasZeroErrorUpToDoubleRounding) {
  // Axis-aligned turns and whole-metre steps are exact numbers, but the devkit's full
  // pivoting divides by the largest entry first, a translation, so the inverses round.
  std::vector<Rigid3d> square = {Rigid3d::Identity()};
  const Eigen::Matrix3d quarter_turn =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix().array().round();
  for (int i = 1; i < 900; ++i) {
    const Eigen::Matrix3d turn = i % 150 == 0 ? quarter_turn : Eigen::Matrix3d::Identity();
    square.push_back(square.back() * MakeRigid3d(turn, Eigen::Vector3d(0, 0, 1)));
  }
  const KittiOdometryResult exact = EvaluateKittiOdometry(square, square);
  ASSERT_GT(exact.n_segments(), 0);
  EXPECT_LT(*exact.t_err, 1e-15f);
  EXPECT_EQ(*exact.r_err, 0.0f);

  // General rotations: the error poses' diagonals are 1 within double rounding, exactly 1
  // once rounded to float, so r_err is 0 (float matrix arithmetic left ~1e-5 deg/m here).
  const std::vector<Rigid3d> drive = testing::CurvyDrive(1500, 1.0);
  const KittiOdometryResult noisy = EvaluateKittiOdometry(drive, drive);
  ASSERT_GT(noisy.n_segments(), 0);
  EXPECT_LT(*noisy.t_err, 1e-12f);
  EXPECT_EQ(*noisy.r_err, 0.0f);
}

// The devkit's own numbers for a perturbed synthetic drive: its evaluate_odometry.cpp error
// computation and Matrix class (double products, Gauss-Jordan inverses with full pivoting;
// distances and errors in float), transcribed line by line into a throwaway program and run
// on these poses written with 17 digits. Float matrix arithmetic misses r_err by ~5e-5.
TEST(KittiOdometryMetric, MatchesTheDevkitToOnePartPerMillion) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(3000, 0.9);
  const std::vector<Rigid3d> est = testing::PerturbedEstimate(gt, 7, 0.05, 0.02, 1e-3);
  const KittiOdometryResult result = EvaluateKittiOdometry(gt, est);
  const auto expect_relatively_near = [](double actual, double expected, const std::string& what) {
    EXPECT_NEAR(actual, expected, 1e-6 * expected) << what;
  };
  ASSERT_EQ(result.n_segments(), 1983);
  expect_relatively_near(*result.t_err, 0.019479163, "t_err");
  expect_relatively_near(*result.r_err, 5.49339784e-05, "r_err");
  expect_relatively_near(result.gt_path_length_m, 2699.55444, "path length");
  struct Expected {
    int n_segments;
    double t_err;
    double r_err;
  };
  const Expected devkit[8] = {
      {286, 0.0230757575, 9.31335526e-05}, {274, 0.0209014881, 6.23063897e-05},
      {265, 0.0202131979, 5.31400947e-05}, {256, 0.0198018495, 4.9886552e-05},
      {244, 0.0191352647, 4.66689853e-05}, {229, 0.018075116, 4.31174813e-05},
      {219, 0.0170350689, 4.08768465e-05}, {210, 0.015885083, 3.88561748e-05}};
  for (int k = 0; k < 8; ++k) {
    const KittiLengthResult& length = result.per_length[k];
    const std::string name = std::to_string(100 * (k + 1)) + " m";
    EXPECT_EQ(length.n_segments, devkit[k].n_segments) << name;
    expect_relatively_near(*length.t_err, devkit[k].t_err, name + " t_err");
    expect_relatively_near(*length.r_err, devkit[k].r_err, name + " r_err");
  }
}

TEST(KittiOdometryMetric, AgreesWithDoubleReferenceOnSyntheticDrive) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(3000, 0.9);
  const std::vector<Rigid3d> est = testing::PerturbedEstimate(gt, 7, 0.05, 0.02, 1e-3);
  ExpectAgreesWithReference(gt, est, 5e-4);
}

TEST(KittiOdometryMetric, AgreesWithDoubleReferenceOnKitti05) {
  ROADSCALE_REQUIRE_SHARED("kitti/poses/05.txt");
  const std::vector<Rigid3d> gt =
      ReadKittiTrajectory(testing::SharedPath("kitti/poses/05.txt").string()).world_from_cam;
  ASSERT_EQ(gt.size(), 2761u);
  const std::vector<Rigid3d> est = testing::PerturbedEstimate(gt, 5, 0.04, 0.01, 1e-3);
  ExpectAgreesWithReference(gt, est, 5e-4);
}

TEST(KittiOdometryMetric, NoLengthFitsAShortTrajectory) {
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(46);  // 45 m
  const KittiOdometryResult result = EvaluateKittiOdometry(gt, gt);
  EXPECT_EQ(result.n_segments(), 0);
  EXPECT_FALSE(result.t_err);
  EXPECT_FALSE(result.r_err);
  EXPECT_EQ(result.gt_path_length_m, 45.0f);
  for (const KittiLengthResult& length : result.per_length) EXPECT_EQ(length.n_segments, 0);
}

TEST(KittiOdometryMetric, RotationErrorFormula) {
  EXPECT_EQ(KittiRotationError(Eigen::Matrix3f::Identity()), 0.0f);
  const Eigen::Matrix3f turn =
      Eigen::AngleAxisf(0.5f, Eigen::Vector3f(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_NEAR(KittiRotationError(turn), 0.5f, 1e-6);
  // Cosines outside [-1, 1] (from rounding) are clamped, never NaN.
  EXPECT_EQ(KittiRotationError(1.01f * Eigen::Matrix3f::Identity()), 0.0f);
  EXPECT_NEAR(KittiRotationError(-Eigen::Matrix3f::Identity()), static_cast<float>(M_PI), 1e-6);
}

TEST(KittiOdometryMetric, PathDistancesAreFloatSums) {
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(5);
  EXPECT_EQ(KittiPathDistances(gt), (std::vector<float>{0, 1, 2, 3, 4}));
}

TEST(KittiOdometryMetric, RejectsMismatchedOrEmptyInput) {
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(20);
  const std::vector<Rigid3d> shorter(gt.begin(), gt.end() - 1);
  try {
    EvaluateKittiOdometry(gt, shorter);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("19 estimated and 20 ground-truth"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(EvaluateKittiOdometry({}, {}), Error);
  // Beyond float's range (3.4e38) the devkit's single-precision errors cannot hold a pose's.
  std::vector<Rigid3d> huge = gt;
  huge[3].translation().x() = 1e39;
  EXPECT_THROW(EvaluateKittiOdometry(gt, huge), Error);
}

TEST(KittiOdometryMetric, OptionsAreChecked) {
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(20);
  KittiMetricOptions options;
  options.step_frames = 0;
  EXPECT_THROW(EvaluateKittiOdometry(gt, gt, options), Error);
  options = {};
  options.lengths_m = {};
  EXPECT_THROW(EvaluateKittiOdometry(gt, gt, options), Error);
  options.lengths_m = {200, 100};
  EXPECT_THROW(EvaluateKittiOdometry(gt, gt, options), Error);
  options.lengths_m = {-5};
  EXPECT_THROW(EvaluateKittiOdometry(gt, gt, options), Error);
  options.lengths_m = {5, 10};
  options.step_frames = 1;
  // 20 frames 1 m apart: 5 m segments start at 0..13, 10 m segments at 0..8.
  EXPECT_EQ(EvaluateKittiOdometry(gt, gt, options).n_segments(), 14 + 9);
}

}  // namespace
}  // namespace roadscale
