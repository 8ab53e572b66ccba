#include "roadscale/synth/road_generator.h"

#include <algorithm>
#include <cmath>

#include "roadscale/geometry/angles.h"

namespace roadscale::synth {
std::vector<RoadPiece> GenerateRoadPieces(const RoadOptions& options, double start, double length,
                                          Rng& rng) {
  std::vector<RoadPiece> pieces;
  double total = 0.0;
  double grade = 0.0;
  bool curve = false;
  while (total < length) {
    RoadPiece piece;
    piece.transition = options.transition;
    // The first piece is flat: frame 0 sees a level road ahead.
    if (!pieces.empty() && rng.Bernoulli(options.grade_change_probability)) {
      grade = rng.Uniform(-options.grade_max, options.grade_max);
    }
    piece.grade = grade;
    if (!curve) {
      piece.length = rng.Uniform(options.straight_min, options.straight_max);
      if (pieces.empty()) piece.length += start;
      piece.curvature = 0.0;
      piece.bank = rng.Uniform(-0.3, 0.3) * options.bank_max_deg * kRadiansPerDegree;
    } else {
      const double direction = rng.Bernoulli(0.5) ? 1.0 : -1.0;
      double radius, angle;
      if (rng.Bernoulli(options.sharp_turn_probability)) {
        radius = rng.Uniform(options.sharp_radius_min, options.sharp_radius_max);
        angle = rng.Uniform(options.sharp_angle_min_deg, options.sharp_angle_max_deg);
      } else {
        // Log-uniform: as many gentle as tight curves per octave of radius.
        radius = options.radius_min *
                 std::exp(rng.Uniform(0.0, std::log(options.radius_max / options.radius_min)));
        angle = rng.Uniform(options.curve_angle_min_deg, options.curve_angle_max_deg);
      }
      piece.curvature = direction / radius;
      // The curvature ramps in over this piece's transition and out over the next one's,
      // so the heading changes by about curvature * length.
      piece.length = std::max(1.0, angle * kRadiansPerDegree * radius);
      piece.transition = std::min(options.transition, 0.4 * piece.length);
      // Bank into the curve: the outer edge is higher.
      piece.bank = -direction * rng.Uniform(0.3, 1.0) * options.bank_max_deg * kRadiansPerDegree;
    }
    total += piece.length;
    pieces.push_back(piece);
    curve = !curve;
  }
  return pieces;
}

}  // namespace roadscale::synth
