#include "roadscale/pipeline/road_scale_source.h"

#include <cmath>
#include <sstream>
#include <unordered_set>
#include <vector>

namespace roadscale {

RoadScaleSource::RoadScaleSource(const PinholeCamera& camera, const ScaleEstimatorOptions& options)
    : estimator_(camera, options) {}

std::string RoadScaleSource::DiagnosticsCsvHeader() const {
  return "road_raw_scale,road_scale,road_inlier_tracks,road_triangulated,road_preselected,"
         "road_after_vote,road_after_model_check,road_ransac_inliers,road_inlier_ratio,"
         "road_plane_nx,road_plane_ny,road_plane_nz,road_plane_h";
}

ScaleResult RoadScaleSource::StepLength(const ScaleQuery& query) {
  ScaleResult result;
  if (query.frontend == nullptr || query.frontend->motion.status != MotionStatus::kOk) {
    result.status = std::string("no motion: ") +
                    (query.frontend == nullptr ? "no frontend result"
                                               : MotionStatusName(query.frontend->motion.status));
    return result;
  }
  const TwoViewMotion& motion = query.frontend->motion;
  const std::unordered_set<int64_t> inliers(motion.inlier_track_ids.begin(),
                                            motion.inlier_track_ids.end());
  std::vector<Eigen::Vector2d> prev_pixels;
  std::vector<Eigen::Vector2d> cur_pixels;
  prev_pixels.reserve(inliers.size());
  cur_pixels.reserve(inliers.size());
  for (const Correspondence& correspondence : query.frontend->correspondences) {
    if (inliers.count(correspondence.track_id) == 0) continue;
    prev_pixels.push_back(correspondence.prev);
    cur_pixels.push_back(correspondence.cur);
  }
  last_estimate_ =
      estimator_.Estimate(prev_pixels, cur_pixels, motion.CurFromPrev(1.0), query.prev_road_mask);
  const ScaleEstimate& estimate = last_estimate_;
  result.valid = estimate.has_scale && std::isfinite(estimate.scale) && estimate.scale > 0.0;
  result.step_length_m = result.valid ? estimate.scale : 0.0;
  result.measured = result.valid && estimate.status == ScaleStatus::kOk;
  result.status = ScaleStatusName(estimate.status);
  std::ostringstream diagnostics;
  diagnostics.precision(6);
  diagnostics << estimate.raw_scale << ',' << estimate.scale << ',' << estimate.num_tracks << ','
              << estimate.num_triangulated << ',' << estimate.num_preselected << ','
              << estimate.num_after_vote << ',' << estimate.num_after_road_model << ','
              << estimate.num_ransac_inliers << ',' << estimate.inlier_ratio << ','
              << estimate.plane.normal.x() << ',' << estimate.plane.normal.y() << ','
              << estimate.plane.normal.z() << ',' << estimate.plane.height;
  result.diagnostics_csv = diagnostics.str();
  return result;
}

}  // namespace roadscale
