#include "roadscale/scale/delaunay.h"

#include <set>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include "roadscale/util/random.h"

namespace roadscale {
namespace {

// True when no point lies strictly inside the circumcircle of the triangle (a, b, c).
bool EmptyCircumcircle(const std::vector<Eigen::Vector2d>& points, const std::array<int, 3>& t) {
  const Eigen::Vector2d a = points[t[0]];
  const Eigen::Vector2d b = points[t[1]];
  const Eigen::Vector2d c = points[t[2]];
  const double d =
      2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
  const Eigen::Vector2d centre(
      (a.squaredNorm() * (b.y() - c.y()) + b.squaredNorm() * (c.y() - a.y()) +
       c.squaredNorm() * (a.y() - b.y())) /
          d,
      (a.squaredNorm() * (c.x() - b.x()) + b.squaredNorm() * (a.x() - c.x()) +
       c.squaredNorm() * (b.x() - a.x())) /
          d);
  const double radius = (a - centre).norm();
  for (const Eigen::Vector2d& p : points) {
    if ((p - centre).norm() < radius * (1.0 - 1e-9)) return false;
  }
  return true;
}

TEST(Delaunay, PointInsideTriangleGivesThreeTriangles) {
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {10, 0}, {5, 10}, {5, 4}};
  const auto triangles = DelaunayTriangles(points);
  ASSERT_EQ(triangles.size(), 3U);
  std::set<std::set<int>> found;
  for (const auto& t : triangles) found.insert({t[0], t[1], t[2]});
  EXPECT_EQ(found, (std::set<std::set<int>>{{0, 1, 3}, {1, 2, 3}, {0, 2, 3}}));
}

TEST(Delaunay, RandomPointsFollowEulerAndEmptyCircle) {
  Rng rng(7);
  std::vector<Eigen::Vector2d> points;
  std::vector<cv::Point2f> cv_points;
  for (int i = 0; i < 300; ++i) {
    const double row = rng.Uniform(190.0, 376.0);        // one draw a statement: argument order is
    points.emplace_back(rng.Uniform(0.0, 1241.0), row);  // the compiler's
    cv_points.emplace_back(static_cast<float>(points.back().x()),
                           static_cast<float>(points.back().y()));
  }
  std::vector<int> hull;
  cv::convexHull(cv_points, hull);
  const auto triangles = DelaunayTriangles(points);
  // A triangulation of n points with h of them on the convex hull has 2n - 2 - h triangles.
  EXPECT_EQ(static_cast<int>(triangles.size()), 2 * 300 - 2 - static_cast<int>(hull.size()));
  for (const auto& t : triangles) EXPECT_TRUE(EmptyCircumcircle(points, t));
}

TEST(Delaunay, DegenerateInputsGiveNoTriangles) {
  EXPECT_TRUE(DelaunayTriangles({}).empty());
  EXPECT_TRUE(DelaunayTriangles({{1, 1}, {2, 2}}).empty());
  EXPECT_TRUE(DelaunayTriangles({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).empty());
  EXPECT_TRUE(DelaunayTriangles({{0, 0}, {0, 0}, {5, 5}}).empty());
}

TEST(Delaunay, DuplicatesAndNonFinitePointsAreLeftOut) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {10, 0}, {0, 0}, {nan, 3}, {5, 10}};
  const auto triangles = DelaunayTriangles(points);
  ASSERT_EQ(triangles.size(), 1U);
  EXPECT_EQ((std::set<int>{triangles[0][0], triangles[0][1], triangles[0][2]}),
            (std::set<int>{0, 1, 4}));
}

}  // namespace
}  // namespace roadscale
