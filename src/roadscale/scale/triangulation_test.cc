#include "roadscale/scale/triangulation.h"

#include <cmath>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

class TriangulationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // 1.3 m forward with a slight turn and a little sideways drift.
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitY()).toRotationMatrix();
    prev_from_cur_ = MakeRigid3d(turn, Eigen::Vector3d(0.1, 0.02, 1.3));
    cur_from_prev_ = prev_from_cur_.inverse();
  }

  void Observe(const Eigen::Vector3d& point) {
    prev_pixels_.push_back(camera_.Project(point));
    cur_pixels_.push_back(camera_.Project(cur_from_prev_ * point));
  }

  PinholeCamera camera_ = KittiOdometryCamera();
  Rigid3d prev_from_cur_;
  Rigid3d cur_from_prev_;
  std::vector<Eigen::Vector2d> prev_pixels_;
  std::vector<Eigen::Vector2d> cur_pixels_;
  TriangulationOptions options_;
};

TEST_F(TriangulationTest, RecoversPointsInUnitsOfTheBaseline) {
  const std::vector<Eigen::Vector3d> points = {
      {0.5, 1.65, 6.0}, {-3.0, 1.65, 12.0}, {4.0, -2.0, 9.0}, {-6.0, 0.5, 15.0}};
  for (const auto& point : points) Observe(point);
  const double baseline = cur_from_prev_.translation().norm();
  const TriangulatedPoints result =
      TriangulateUnitBaseline(prev_pixels_, cur_pixels_, cur_from_prev_, camera_, options_);
  ASSERT_EQ(result.points.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(result.track_indices[i], static_cast<int>(i));
    EXPECT_LT((result.points[i] * baseline - points[i]).norm(), 1e-9 * points[i].norm());
  }
  // Only the direction of the translation matters.
  Rigid3d longer = cur_from_prev_;
  longer.translation() *= 7.0;
  const TriangulatedPoints same =
      TriangulateUnitBaseline(prev_pixels_, cur_pixels_, longer, camera_, options_);
  ASSERT_EQ(same.points.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_LT((same.points[i] - result.points[i]).norm(), 1e-9 * result.points[i].norm());
  }
}

TEST_F(TriangulationTest, RejectsPointsBehindTheCurrentCamera) {
  // Between the two cameras: in front of the previous one, behind the current one.
  Observe({0.3, 0.4, 0.6});
  Observe({0.5, 1.65, 6.0});
  const TriangulatedPoints result =
      TriangulateUnitBaseline(prev_pixels_, cur_pixels_, cur_from_prev_, camera_, options_);
  EXPECT_EQ(result.num_behind_camera, 1);
  ASSERT_EQ(result.track_indices, std::vector<int>{1});
}

TEST_F(TriangulationTest, RejectsPointsWithTinyParallax) {
  Observe({5.0, 1.0, 400.0});  // about 0.06 deg of parallax
  Observe({0.5, 1.65, 8.0});   // about 1.6 deg
  const TriangulatedPoints result =
      TriangulateUnitBaseline(prev_pixels_, cur_pixels_, cur_from_prev_, camera_, options_);
  EXPECT_EQ(result.num_small_parallax, 1);
  ASSERT_EQ(result.track_indices, std::vector<int>{1});
}

TEST_F(TriangulationTest, RejectsMismatchesByReprojectionError) {
  Observe({-2.0, 1.65, 7.0});
  Observe({2.0, 1.65, 7.0});
  // Move the first current pixel 5 px across its epipolar line: no point explains both.
  const Eigen::Matrix3d rotation = cur_from_prev_.linear();
  const Eigen::Vector3d t = cur_from_prev_.translation();
  Eigen::Matrix3d t_cross;
  t_cross << 0, -t.z(), t.y(), t.z(), 0, -t.x(), -t.y(), t.x(), 0;
  const Eigen::Matrix3d k_inv = camera_.K().inverse();
  const Eigen::Matrix3d fundamental = k_inv.transpose() * t_cross * rotation * k_inv;
  const Eigen::Vector3d line = fundamental * prev_pixels_[0].homogeneous();
  cur_pixels_[0] += 5.0 * line.head<2>().normalized();
  const TriangulatedPoints result =
      TriangulateUnitBaseline(prev_pixels_, cur_pixels_, cur_from_prev_, camera_, options_);
  EXPECT_EQ(result.num_large_reprojection_error, 1);
  ASSERT_EQ(result.track_indices, std::vector<int>{1});
}

TEST_F(TriangulationTest, MismatchedListsAreAnError) {
  Observe({0.5, 1.65, 6.0});
  cur_pixels_.push_back({1.0, 2.0});
  EXPECT_THROW(
      TriangulateUnitBaseline(prev_pixels_, cur_pixels_, cur_from_prev_, camera_, options_), Error);
}

TEST(TriangulationOptions, CheckRejectsBadValues) {
  TriangulationOptions options;
  EXPECT_NO_THROW(options.Check());
  options.max_reprojection_error_px = 0.0;
  EXPECT_THROW(options.Check(), Error);
  options = TriangulationOptions();
  options.min_parallax_deg = -1.0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale
