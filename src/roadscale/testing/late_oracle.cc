#include "roadscale/testing/late_oracle.h"

#include <utility>

namespace roadscale::testing {

LateOracle::LateOracle(Trajectory ground_truth, size_t first_scaled)
    : oracle_(std::move(ground_truth)), first_scaled_(first_scaled) {}

ScaleResult LateOracle::StepLength(const ScaleQuery& query) {
  if (query.position < first_scaled_) return ScaleResult();
  return oracle_.StepLength(query);
}

}  // namespace roadscale::testing
