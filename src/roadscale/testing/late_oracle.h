#pragma once

#include <cstddef>
#include <string>

#include "roadscale/io/trajectory_io.h"
#include "roadscale/pipeline/oracle_scale_source.h"
#include "roadscale/pipeline/scale_source.h"

namespace roadscale::testing {

// The oracle's lengths (the ground truth's steps) from run position `first_scaled` on only:
// the frames before it have no scale, as a drive whose road is found late.
class LateOracle : public ScaleSource {
 public:
  LateOracle(Trajectory ground_truth, size_t first_scaled);
  std::string Name() const override { return "late oracle"; }
  ScaleResult StepLength(const ScaleQuery& query) override;

 private:
  OracleScaleSource oracle_;
  size_t first_scaled_;
};

}  // namespace roadscale::testing
