#pragma once

#include <string>

#include "roadscale/io/trajectory_io.h"
#include "roadscale/pipeline/scale_source.h"

namespace roadscale {

// The length of each step taken from ground-truth poses, as mono-vo's "absolute scale" does:
// it isolates the frontend's error (rotation, direction) from the scale module's.
class OracleScaleSource : public ScaleSource {
 public:
  // `ground_truth` holds one world_from_cam per frame of the run, in order (position 0 =
  // first frame processed), as FrameSource::ground_truth() returns it.
  explicit OracleScaleSource(Trajectory ground_truth);

  std::string Name() const override { return "oracle"; }
  // |c_k - c_{k-1}| of the ground-truth camera centres at query.position and the one before.
  // Throws Error when the ground truth has no pose for query.position.
  ScaleResult StepLength(const ScaleQuery& query) override;

 private:
  Trajectory ground_truth_;
};

}  // namespace roadscale
