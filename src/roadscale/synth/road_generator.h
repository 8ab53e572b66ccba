#pragma once

#include <vector>

#include "roadscale/synth/centre_line.h"
#include "roadscale/synth/scene_options.h"
#include "roadscale/util/random.h"

namespace roadscale::synth {

// Random road pieces of at least `length` metres: straights and curves alternating, each
// curve turning by a random angle (sharp junction-like turns with the configured
// probability), grades changing between pieces and banking into curves. The first piece is
// a straight that covers `start` metres plus a random straight length, so the sequence does
// not begin inside a curve.
std::vector<RoadPiece> GenerateRoadPieces(const RoadOptions& options, double start, double length,
                                          Rng& rng);

}  // namespace roadscale::synth
