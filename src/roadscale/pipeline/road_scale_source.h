#pragma once

#include <string>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/pipeline/scale_source.h"
#include "roadscale/scale/scale_estimator.h"

namespace roadscale {

// The paper's road-plane scale (section III, roadscale/scale/) as the pipeline's scale source:
// the frontend's inlier tracks and two-view motion go in, h0 / h (filtered) comes out. The
// scale module itself knows nothing of the frontend; this adapter is the only place where the
// two meet.
class RoadScaleSource : public ScaleSource {
 public:
  // options.camera_height is h0. Throws Error on invalid options or camera.
  RoadScaleSource(const PinholeCamera& camera, const ScaleEstimatorOptions& options);

  std::string Name() const override { return "road"; }
  // Frames whose motion is not kOk (stationary, pure rotation, too few inliers) have no
  // translation direction to scale: invalid, status "no motion: <motion status>". Otherwise
  // the estimator's filtered scale, valid once a first road plane was fitted; the status is
  // the estimator's ("ok", "held: too few points", ...).
  ScaleResult StepLength(const ScaleQuery& query) override;
  std::string DiagnosticsCsvHeader() const override;

  // The estimator's full result for the last frame that had a motion.
  const ScaleEstimate& last_estimate() const { return last_estimate_; }

 private:
  ScaleEstimator estimator_;
  ScaleEstimate last_estimate_;
};

}  // namespace roadscale
