#include "roadscale/synth/centre_line.h"

#include <cmath>

#include <gtest/gtest.h>

namespace roadscale::synth {
namespace {

TEST(PiecewiseLinear, ValuesSlopesAndExactIntegral) {
  PiecewiseLinear f;
  f.AddKnot(0.0, 1.0);
  f.AddKnot(2.0, 3.0);
  f.AddKnot(2.0, -1.0);  // a step
  f.AddKnot(4.0, -1.0);
  EXPECT_DOUBLE_EQ(f.Value(-1.0), 1.0);
  EXPECT_DOUBLE_EQ(f.Value(1.0), 2.0);
  EXPECT_DOUBLE_EQ(f.Value(3.0), -1.0);
  EXPECT_DOUBLE_EQ(f.Value(9.0), -1.0);
  EXPECT_DOUBLE_EQ(f.Slope(1.0), 1.0);
  EXPECT_DOUBLE_EQ(f.Integral(1.0), 1.5);
  EXPECT_DOUBLE_EQ(f.Integral(2.0), 4.0);
  EXPECT_DOUBLE_EQ(f.Integral(3.0), 3.0);
  EXPECT_DOUBLE_EQ(f.Integral(5.0), 1.0);  // constant beyond the last knot
}

TEST(CentreLine, QuarterCircleEndsWhereGeometrySays) {
  const double radius = 20.0;
  const double quarter = 0.5 * M_PI * radius;
  const CentreLine line({{quarter, 1.0 / radius, 0.0, 0.0, 0.0}});
  const RoadFrame end = line.FrameAt(quarter);
  EXPECT_NEAR(end.point.x(), radius, 1e-9);
  EXPECT_NEAR(end.point.y(), radius, 1e-9);
  EXPECT_NEAR(end.heading, 0.5 * M_PI, 1e-12);
  // Halfway round, on the circle about (0, radius).
  const RoadFrame half = line.FrameAt(0.5 * quarter);
  EXPECT_NEAR((half.point.head<2>() - Eigen::Vector2d(0.0, radius)).norm(), radius, 1e-9);
}

TEST(CentreLine, ClothoidTurnsByItsCurvatureIntegral) {
  // Curvature ramps from 0 to 1/50 over 30 m, stays for 70 m: the heading at 100 m is
  // (15 + 70) / 50 rad, and straight again after the next piece's 30 m ramp-out.
  const CentreLine line({{100.0, 1.0 / 50.0, 0.0, 0.0, 30.0}, {100.0, 0.0, 0.0, 0.0, 30.0}});
  EXPECT_NEAR(line.FrameAt(100.0).heading, 85.0 / 50.0, 1e-12);
  EXPECT_NEAR(line.FrameAt(200.0).heading, 100.0 / 50.0, 1e-12);
  EXPECT_NEAR(line.FrameAt(115.0).curvature, 0.5 / 50.0, 1e-12);
  // Positions integrate the heading: a finite difference recovers the tangent.
  const double u = 57.3, h = 1e-4;
  const Eigen::Vector3d derivative =
      (line.FrameAt(u + h).point - line.FrameAt(u - h).point) / (2.0 * h);
  EXPECT_NEAR(derivative.x(), std::cos(line.FrameAt(u).heading), 1e-7);
  EXPECT_NEAR(derivative.y(), std::sin(line.FrameAt(u).heading), 1e-7);
}

TEST(CentreLine, GradeGivesHeightAndArcLength) {
  const CentreLine line({{200.0, 0.0, 0.05, 0.0, 0.0}});
  EXPECT_NEAR(line.FrameAt(100.0).point.z(), 5.0, 1e-12);
  EXPECT_NEAR(line.ArcLength(100.0), 100.0 * std::sqrt(1.0 + 0.0025), 1e-9);
  const RoadFrame frame = line.FrameAt(100.0);
  EXPECT_NEAR(frame.tangent.z(), 0.05 / std::sqrt(1.0 + 0.0025), 1e-12);
}

TEST(CentreLine, FrameIsOrthonormalAndBanked) {
  const double bank = 0.05;
  const CentreLine line({{60.0, 0.0, 0.0, 0.0, 10.0}, {80.0, -1.0 / 30.0, 0.04, bank, 20.0}});
  for (double u : {0.0, 30.0, 65.0, 79.0, 100.0, 139.0, 200.0}) {
    const RoadFrame f = line.FrameAt(u);
    EXPECT_NEAR(f.tangent.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.lateral.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.tangent.dot(f.lateral), 0.0, 1e-12);
    EXPECT_NEAR(f.tangent.dot(f.normal), 0.0, 1e-12);
    EXPECT_NEAR(f.lateral.dot(f.normal), 0.0, 1e-12);
    EXPECT_NEAR((f.tangent.cross(f.lateral) - f.normal).norm(), 0.0, 1e-12);
    EXPECT_GT(f.normal.z(), 0.9);
    // The surface point at l is on the lateral line; SurfacePoint agrees with the frame.
    EXPECT_NEAR((line.SurfacePoint(u, 2.0) - (f.point + 2.0 * f.lateral)).norm(), 0.0, 1e-12);
  }
  // Fully banked: the left edge is higher by sin(bank) per metre.
  const RoadFrame f = line.FrameAt(120.0);
  EXPECT_NEAR(f.bank, bank, 1e-12);
  EXPECT_NEAR(std::asin(f.lateral.z() / std::cos(std::atan(0.04))), bank, 1e-12);
  // The normal is the surface normal along l = 0: perpendicular to dP/du.
  const Eigen::Vector3d du =
      (line.SurfacePoint(120.0 + 1e-5, 0.0) - line.SurfacePoint(120.0 - 1e-5, 0.0)) / 2e-5;
  EXPECT_NEAR(du.normalized().dot(f.normal), 0.0, 1e-8);
}

TEST(CentreLine, CrownFallsToBothEdgesFromTheMiddle) {
  // Carriageway from l = -4 to l = 6: apex at l = 1, 2 % cross fall at the edges.
  const CentreLine line({{100.0, 0.0, 0.0, 0.0, 0.0}}, RoadCrown{0.02, -4.0, 6.0});
  auto height = [&](double l) { return line.SurfacePoint(50.0, l).z(); };
  EXPECT_GT(height(1.0), height(0.9));
  EXPECT_GT(height(1.0), height(1.1));
  EXPECT_NEAR((height(6.0) - height(5.99)) / 0.01, -0.02, 1e-3);
  EXPECT_NEAR((height(-3.99) - height(-4.0)) / 0.01, 0.02, 1e-3);
  // Beyond the edges the surface keeps the edge's offset from the tangent plane.
  EXPECT_DOUBLE_EQ(line.CrownOffset(9.0), line.CrownOffset(6.0));
  // At l = 0 the frame is the tangent plane: no offset, no slope along the lateral.
  EXPECT_EQ(line.CrownOffset(0.0), 0.0);
  const RoadFrame f = line.FrameAt(50.0);
  const Eigen::Vector3d dl =
      (line.SurfacePoint(50.0, 1e-5) - line.SurfacePoint(50.0, -1e-5)) / 2e-5;
  EXPECT_NEAR(dl.dot(f.normal), 0.0, 1e-9);
  EXPECT_NEAR(f.bank, std::atan(0.02 / 5.0 * 1.0), 1e-12);
}

}  // namespace
}  // namespace roadscale::synth
