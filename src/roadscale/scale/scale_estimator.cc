#include "roadscale/scale/scale_estimator.h"

#include <cmath>
#include <limits>
#include <optional>

#include <opencv2/imgproc.hpp>

#include "roadscale/geometry/camera_height.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

template <typename T>
std::vector<T> Gather(const std::vector<T>& values, const std::vector<int>& indices) {
  std::vector<T> gathered;
  gathered.reserve(indices.size());
  for (int index : indices) gathered.push_back(values[index]);
  return gathered;
}

// indices[kept[k]] for every k: maps a stage's output back to the input of the first stage.
std::vector<int> Compose(const std::vector<int>& indices, const std::vector<int>& kept) {
  std::vector<int> composed;
  composed.reserve(kept.size());
  for (int k : kept) composed.push_back(indices[k]);
  return composed;
}

}  // namespace

void ScaleEstimatorOptions::Check() const {
  CheckCameraHeight(camera_height, "scale.camera_height");
  homography.Check();
  triangulation.Check();
  depth_vote.Check();
  road_model.Check();
  ransac.Check();
  filter.Check();
}

const char* ScaleStatusName(ScaleStatus status) {
  switch (status) {
    case ScaleStatus::kOk:
      return "ok";
    case ScaleStatus::kHeldTooFewPoints:
      return "held: too few points";
    case ScaleStatus::kHeldDegenerate:
      return "held: degenerate";
    case ScaleStatus::kNoMotion:
      return "no motion";
  }
  return "unknown";
}

ScaleEstimator::ScaleEstimator(const PinholeCamera& camera, const ScaleEstimatorOptions& options)
    : camera_(camera), options_(options), filter_(options.filter) {
  camera_.Check();
  options_.Check();
}

void ScaleEstimator::Reset() {
  filter_.Reset();
  has_model_ = false;
  last_plane_ = Plane();
  last_raw_scale_ = 0.0;
}

ScaleEstimate ScaleEstimator::Estimate(const std::vector<Eigen::Vector2d>& prev_pixels,
                                       const std::vector<Eigen::Vector2d>& cur_pixels,
                                       const Rigid3d& cur_from_prev,
                                       const cv::Mat& prev_road_mask) {
  ScaleEstimate estimate;
  estimate.num_tracks = static_cast<int>(prev_pixels.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();

  const auto finish_held = [&](ScaleStatus status) {
    estimate.status = status;
    estimate.plane = last_plane_;
    estimate.has_scale = has_model_;
    estimate.raw_scale = has_model_ ? last_raw_scale_ : nan;
    // A held frame's scale comes from the kept road model (the paper's reading of eq. 13 for
    // such frames), so it enters the window like any other; a frame without motion has no
    // scale of its own and leaves the window as it is.
    if (!options_.use_filter) {
      estimate.scale = estimate.raw_scale;
    } else if (has_model_ && status != ScaleStatus::kNoMotion) {
      estimate.scale = filter_.Add(last_raw_scale_);
    } else {
      estimate.scale = has_model_ ? filter_.Current() : nan;
    }
    return estimate;
  };

  if (prev_pixels.size() != cur_pixels.size()) {
    throw Error("scale estimator: " + std::to_string(prev_pixels.size()) + " previous pixels but " +
                std::to_string(cur_pixels.size()) +
                " current pixels; expected one current pixel per previous pixel");
  }
  const std::optional<Eigen::Vector3d> road_normal =
      ExpectedRoadNormal(cur_from_prev, options_.road_model);
  if (!TravelDirection(cur_from_prev) || !road_normal) return finish_held(ScaleStatus::kNoMotion);

  const TriangulatedPoints triangulated = TriangulateUnitBaseline(
      prev_pixels, cur_pixels, cur_from_prev, camera_, options_.triangulation);
  estimate.num_triangulated = static_cast<int>(triangulated.points.size());
  estimate.num_behind_camera = triangulated.num_behind_camera;
  estimate.num_small_parallax = triangulated.num_small_parallax;
  estimate.num_large_reprojection_error = triangulated.num_large_reprojection_error;
  const std::vector<Eigen::Vector2d> pixels = Gather(prev_pixels, triangulated.track_indices);

  // `selection` indexes triangulated.points throughout.
  estimate.used_road_mask = options_.use_segmentation && !prev_road_mask.empty();
  std::vector<int> selection = PreselectRoadCandidates(
      pixels, triangulated.points, estimate.used_road_mask ? prev_road_mask : cv::Mat(),
      options_.use_horizon ? road_normal : std::nullopt);
  estimate.num_preselected = static_cast<int>(selection.size());

  if (options_.use_depth_vote) {
    const DepthConsistencyVote vote = VoteOnDepthConsistency(
        Gather(pixels, selection), Gather(triangulated.points, selection), options_.depth_vote);
    selection = Compose(selection, vote.kept);
  }
  estimate.num_after_vote = static_cast<int>(selection.size());

  if (options_.use_road_model_check) {
    const RoadModelCheck check =
        CheckRoadModel(Gather(pixels, selection), Gather(triangulated.points, selection),
                       *road_normal, options_.road_model);
    selection = Compose(selection, check.kept);
  }
  estimate.num_after_road_model = static_cast<int>(selection.size());
  estimate.candidate_track_indices = Compose(triangulated.track_indices, selection);

  const RoadPlaneFit fit =
      FitRoadPlaneRansac(Gather(triangulated.points, selection), *road_normal, options_.ransac);
  estimate.num_ransac_inliers = static_cast<int>(fit.inliers.size());
  estimate.inlier_ratio = fit.inlier_ratio;
  if (fit.status == RoadPlaneFit::Status::kTooFewPoints) {
    return finish_held(ScaleStatus::kHeldTooFewPoints);
  }
  if (fit.status == RoadPlaneFit::Status::kDegenerate) {
    return finish_held(ScaleStatus::kHeldDegenerate);
  }

  Plane plane = fit.plane;
  const std::vector<int> inliers = Compose(selection, fit.inliers);  // into triangulated
  if (options_.homography_refit) {
    const std::optional<RoadHomographyRefit> refit =
        RefitRoadHomography(pixels, Gather(cur_pixels, triangulated.track_indices), inliers,
                            cur_from_prev, camera_, plane, options_.homography);
    if (!refit) return finish_held(ScaleStatus::kHeldDegenerate);
    plane = refit->plane;
  }

  has_model_ = true;
  last_plane_ = plane;
  last_raw_scale_ = options_.camera_height / plane.height;
  estimate.status = ScaleStatus::kOk;
  estimate.has_scale = true;
  estimate.plane = plane;
  estimate.raw_scale = last_raw_scale_;
  estimate.scale = options_.use_filter ? filter_.Add(last_raw_scale_) : last_raw_scale_;
  estimate.road_track_indices = Compose(triangulated.track_indices, inliers);
  return estimate;
}

}  // namespace roadscale
