#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace roadscale::synth {

// A function of arc position given by its values at increasing knots, linear in between and
// constant outside; its integral is exact.
class PiecewiseLinear {
 public:
  // Knots must come in increasing order of `u` (equal u values make a step).
  void AddKnot(double u, double value);
  double Value(double u) const;
  double Slope(double u) const;
  // Integral from the first knot to u.
  double Integral(double u) const;
  bool empty() const { return u_.empty(); }

 private:
  size_t Interval(double u) const;
  std::vector<double> u_, value_, cumulative_;
};

// One piece of road: over `length` metres the curvature, grade and bank move linearly from
// the previous piece's values to this piece's values within the first `transition` metres
// (a clothoid for the curvature, a vertical curve for the grade), then stay constant.
struct RoadPiece {
  double length = 100.0;     // horizontal length, metres
  double curvature = 0.0;    // 1/m, positive turns left
  double grade = 0.0;        // dz per horizontal metre, positive climbs
  double bank = 0.0;         // radians, positive raises the left edge
  double transition = 20.0;  // metres
};

// The road's reference frame at horizontal arc position u. The road surface is the ruled
// surface P(u, l) = point + l * lateral; `normal` is its exact unit normal along l = 0,
// because `tangent` (= dP/du normalised) and `lateral` span the tangent plane there.
struct RoadFrame {
  Eigen::Vector3d point;            // on the surface, l = 0
  Eigen::Vector3d tangent;          // unit, direction of travel
  Eigen::Vector3d lateral;          // unit, to the left, in the banked surface
  Eigen::Vector3d normal;           // unit, up, tangent x lateral
  Eigen::Vector3d horizontal_left;  // unit, to the left, horizontal
  double heading = 0.0;             // radians, counter-clockwise from world x
  double curvature = 0.0;
  double grade = 0.0;
  double bank = 0.0;
};

// A crowned road: the carriageway between l_right and l_left falls to both edges with
// `slope` (dz per metre across, at the edges) from an apex at its middle. Seen from the ego
// lane centre (l = 0) this is a cross slope there, which tilts the road frame like bank, and
// a parabola -curvature * l^2 below that tangent plane; beyond the edges the surface keeps
// the edges' offset.
struct RoadCrown {
  double slope = 0.0;
  double l_right = 0.0, l_left = 0.0;
};

// The ego vehicle's lane centre as a 3-D curve in a world frame with z up, starting at the
// origin heading along +x. It is parameterised by the horizontal arc length u (metres),
// so C'(u) = (cos heading, sin heading, grade) in closed form; x and y are integrated with
// Gauss-Legendre quadrature on sub-intervals that never straddle a knot (error ~1e-12 m).
class CentreLine {
 public:
  explicit CentreLine(const std::vector<RoadPiece>& pieces, const RoadCrown& crown = {});

  // Total horizontal length of the pieces; frames beyond it continue the last piece.
  double length() const { return length_; }
  RoadFrame FrameAt(double u) const;
  // A point of the road surface at lateral offset l (positive left), `height` above it
  // along the frame's normal. The surface is P(u, l) = point + l lateral + crown(l) normal,
  // with crown(0) = crown'(0) = 0: at l = 0 the frame's normal is the exact surface normal.
  Eigen::Vector3d SurfacePoint(double u, double l) const;
  Eigen::Vector3d SurfacePoint(const RoadFrame& frame, double l, double height = 0.0) const {
    return frame.point + l * frame.lateral + (height + CrownOffset(l)) * frame.normal;
  }
  // crown(l): the surface's offset along the normal from the tangent plane at l = 0.
  double CrownOffset(double l) const {
    const double x = l < crown_.l_right ? crown_.l_right : (l > crown_.l_left ? crown_.l_left : l);
    return -crown_curvature_ * x * x;
  }
  // Arc length along the 3-D curve between u = 0 and u.
  double ArcLength(double u) const;
  const std::vector<RoadPiece>& pieces() const { return pieces_; }

 private:
  Eigen::Vector2d IntegrateXY(double u0, double u1) const;
  double Heading(double u) const { return curvature_.Integral(u); }

  std::vector<RoadPiece> pieces_;
  RoadCrown crown_;
  double crown_curvature_ = 0.0;  // of the crown parabola, 1/m
  double crown_bank_ = 0.0;       // the cross slope at l = 0, radians
  double length_ = 0.0;
  PiecewiseLinear curvature_, grade_, bank_;
  std::vector<double> table_u_;
  std::vector<Eigen::Vector2d> table_xy_;
  std::vector<double> table_arc_;
};

}  // namespace roadscale::synth
