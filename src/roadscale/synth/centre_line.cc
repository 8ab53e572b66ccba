#include "roadscale/synth/centre_line.h"

#include <algorithm>
#include <cmath>

#include "roadscale/util/error.h"

#include <Eigen/Geometry>

namespace roadscale::synth {
namespace {

// 6-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double kNodes[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                              0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
constexpr double kWeights[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                0.4679139345726910, 0.3607615730481386, 0.1713244923791704};

// Table nodes at most this far apart (metres).
constexpr double kTableStep = 1.0;

}  // namespace

void PiecewiseLinear::AddKnot(double u, double value) {
  if (!u_.empty() && u < u_.back()) throw Error("PiecewiseLinear: knots must not decrease");
  if (u_.empty()) {
    cumulative_.push_back(0.0);
  } else {
    cumulative_.push_back(cumulative_.back() + 0.5 * (value_.back() + value) * (u - u_.back()));
  }
  u_.push_back(u);
  value_.push_back(value);
}

size_t PiecewiseLinear::Interval(double u) const {
  // Index i with u_[i] <= u < u_[i+1]; the last knot at or below u.
  const auto it = std::upper_bound(u_.begin(), u_.end(), u);
  return it == u_.begin() ? 0 : static_cast<size_t>(it - u_.begin()) - 1;
}

double PiecewiseLinear::Value(double u) const {
  if (u_.empty()) return 0.0;
  if (u <= u_.front()) return value_.front();
  if (u >= u_.back()) return value_.back();
  const size_t i = Interval(u);
  const double span = u_[i + 1] - u_[i];
  if (span <= 0.0) return value_[i + 1];
  const double a = (u - u_[i]) / span;
  return value_[i] + a * (value_[i + 1] - value_[i]);
}

double PiecewiseLinear::Slope(double u) const {
  if (u_.size() < 2 || u < u_.front() || u >= u_.back()) return 0.0;
  const size_t i = Interval(u);
  const double span = u_[i + 1] - u_[i];
  return span > 0.0 ? (value_[i + 1] - value_[i]) / span : 0.0;
}

double PiecewiseLinear::Integral(double u) const {
  if (u_.empty()) return 0.0;
  if (u <= u_.front()) return value_.front() * (u - u_.front());
  if (u >= u_.back()) return cumulative_.back() + value_.back() * (u - u_.back());
  const size_t i = Interval(u);
  const double v = Value(u);
  return cumulative_[i] + 0.5 * (value_[i] + v) * (u - u_[i]);
}

CentreLine::CentreLine(const std::vector<RoadPiece>& pieces, const RoadCrown& crown)
    : pieces_(pieces), crown_(crown) {
  if (pieces.empty()) throw Error("a road needs at least one piece");
  const double half_width = 0.5 * (crown.l_left - crown.l_right);
  if (crown.slope != 0.0 && half_width > 0.0) {
    crown_curvature_ = crown.slope / (2.0 * half_width);
    // The apex at the carriageway's middle: at l = 0 the road rises towards it.
    crown_bank_ = std::atan(2.0 * crown_curvature_ * 0.5 * (crown.l_left + crown.l_right));
  }
  // Knots of the three profiles; every piece's start and end of transition.
  std::vector<double> knots = {0.0};
  double u = 0.0;
  double kappa = 0.0, grade = 0.0, bank = 0.0;
  curvature_.AddKnot(0.0, 0.0);
  grade_.AddKnot(0.0, 0.0);
  bank_.AddKnot(0.0, 0.0);
  for (const RoadPiece& piece : pieces) {
    if (!(piece.length > 0.0) || !(piece.transition >= 0.0)) {
      throw Error("a road piece needs a positive length and a non-negative transition");
    }
    const double transition = std::min(piece.transition, 0.5 * piece.length);
    curvature_.AddKnot(u, kappa);
    grade_.AddKnot(u, grade);
    bank_.AddKnot(u, bank);
    kappa = piece.curvature;
    grade = piece.grade;
    bank = piece.bank;
    curvature_.AddKnot(u + transition, kappa);
    grade_.AddKnot(u + transition, grade);
    bank_.AddKnot(u + transition, bank);
    knots.push_back(u + transition);
    u += piece.length;
    knots.push_back(u);
  }
  length_ = u;

  // Table of x, y and arc length at nodes no more than kTableStep apart, including every
  // knot, so that each quadrature interval sees a smooth integrand.
  table_u_.push_back(0.0);
  for (size_t k = 1; k < knots.size(); ++k) {
    const double a = knots[k - 1], b = knots[k];
    if (b <= a) continue;
    const int steps = static_cast<int>(std::ceil((b - a) / kTableStep));
    for (int s = 1; s <= steps; ++s) table_u_.push_back(a + (b - a) * s / steps);
  }
  table_xy_.push_back(Eigen::Vector2d::Zero());
  table_arc_.push_back(0.0);
  for (size_t i = 1; i < table_u_.size(); ++i) {
    const double a = table_u_[i - 1], b = table_u_[i];
    table_xy_.push_back(table_xy_.back() + IntegrateXY(a, b));
    double arc = 0.0;
    for (int k = 0; k < 6; ++k) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * kNodes[k];
      const double g = grade_.Value(x);
      arc += kWeights[k] * std::sqrt(1.0 + g * g);
    }
    table_arc_.push_back(table_arc_.back() + 0.5 * (b - a) * arc);
  }
}

Eigen::Vector2d CentreLine::IntegrateXY(double u0, double u1) const {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int k = 0; k < 6; ++k) {
    const double x = 0.5 * (u0 + u1) + 0.5 * (u1 - u0) * kNodes[k];
    const double heading = Heading(x);
    sum += kWeights[k] * Eigen::Vector2d(std::cos(heading), std::sin(heading));
  }
  return 0.5 * (u1 - u0) * sum;
}

double CentreLine::ArcLength(double u) const {
  if (u <= 0.0) return u * std::sqrt(1.0 + std::pow(grade_.Value(0.0), 2));
  if (u >= table_u_.back()) {
    const double g = grade_.Value(u);
    return table_arc_.back() + (u - table_u_.back()) * std::sqrt(1.0 + g * g);
  }
  const auto it = std::upper_bound(table_u_.begin(), table_u_.end(), u);
  const size_t i = static_cast<size_t>(it - table_u_.begin()) - 1;
  double arc = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double x = 0.5 * (table_u_[i] + u) + 0.5 * (u - table_u_[i]) * kNodes[k];
    const double g = grade_.Value(x);
    arc += kWeights[k] * std::sqrt(1.0 + g * g);
  }
  return table_arc_[i] + 0.5 * (u - table_u_[i]) * arc;
}

RoadFrame CentreLine::FrameAt(double u) const {
  RoadFrame frame;
  frame.heading = Heading(u);
  frame.curvature = curvature_.Value(u);
  frame.grade = grade_.Value(u);
  frame.bank = bank_.Value(u) + crown_bank_;

  Eigen::Vector2d xy;
  if (u <= 0.0) {
    xy = IntegrateXY(0.0, u);
  } else if (u >= table_u_.back()) {
    xy = table_xy_.back() + IntegrateXY(table_u_.back(), u);
  } else {
    const auto it = std::upper_bound(table_u_.begin(), table_u_.end(), u);
    const size_t i = static_cast<size_t>(it - table_u_.begin()) - 1;
    xy = table_xy_[i] + IntegrateXY(table_u_[i], u);
  }
  frame.point = Eigen::Vector3d(xy.x(), xy.y(), grade_.Integral(u));

  const double c = std::cos(frame.heading), s = std::sin(frame.heading);
  frame.tangent = Eigen::Vector3d(c, s, frame.grade).normalized();
  frame.horizontal_left = Eigen::Vector3d(-s, c, 0.0);
  const Eigen::Vector3d up = frame.tangent.cross(frame.horizontal_left);
  const double cb = std::cos(frame.bank), sb = std::sin(frame.bank);
  frame.lateral = cb * frame.horizontal_left + sb * up;
  frame.normal = cb * up - sb * frame.horizontal_left;
  return frame;
}

Eigen::Vector3d CentreLine::SurfacePoint(double u, double l) const {
  return SurfacePoint(FrameAt(u), l);
}

}  // namespace roadscale::synth
