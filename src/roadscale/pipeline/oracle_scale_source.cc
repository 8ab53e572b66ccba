#include "roadscale/pipeline/oracle_scale_source.h"

#include <utility>

#include "roadscale/util/error.h"

namespace roadscale {

OracleScaleSource::OracleScaleSource(Trajectory ground_truth)
    : ground_truth_(std::move(ground_truth)) {}

ScaleResult OracleScaleSource::StepLength(const ScaleQuery& query) {
  if (query.position == 0 || query.position >= ground_truth_.size()) {
    throw Error("oracle scale: no ground-truth pose for frame " +
                std::to_string(query.frame_index) + " (position " + std::to_string(query.position) +
                " of " + std::to_string(ground_truth_.size()) + " poses)");
  }
  ScaleResult result;
  result.valid = true;
  result.measured = true;
  result.step_length_m = (ground_truth_.world_from_cam[query.position].translation() -
                          ground_truth_.world_from_cam[query.position - 1].translation())
                             .norm();
  result.status = "oracle";
  return result;
}

}  // namespace roadscale
