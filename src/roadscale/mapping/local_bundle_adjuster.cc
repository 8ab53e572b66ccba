#include "roadscale/mapping/local_bundle_adjuster.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include <ceres/loss_function.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include "roadscale/mapping/camera_height_residual.h"
#include "roadscale/mapping/pose_parameters.h"
#include "roadscale/mapping/reprojection_residual.h"
#include "roadscale/mapping/road_pair_residual.h"
#include "roadscale/mapping/two_row_residual.h"
#include "roadscale/util/error.h"
#include "roadscale/util/median.h"

namespace roadscale {
namespace {

double ReprojectionError(const PinholeCamera& camera, const Rigid3d& cam_from_world,
                         const Eigen::Vector3d& point_world, const Eigen::Vector2d& observed) {
  const Eigen::Vector3d point_cam = cam_from_world * point_world;
  if (point_cam.z() < kMinDepthInFront) return std::numeric_limits<double>::infinity();
  return (camera.Project(point_cam) - observed).norm();
}

// Road pairs that must agree (within the outlier bound of their median) to outvote the map:
// one wrong pair cannot set the median of three.
constexpr size_t kMinRoadPairsToOutvoteTheMap = 3;

// Takes out of the adjustment the road pairs whose camera height under the adjusted window
// (metres: height per baseline times the window's baseline) is more than `max_offset` off h0,
// unless it is within `max_offset` of the median of the window's pairs and at least
// kMinRoadPairsToOutvoteTheMap pairs are. The map's scale drifts between road fixes (a grade
// change bends the road under the sparse road points, a car cutting in hides the road): pairs
// that all disagree with the map by the same amount are the map's error, not theirs, and
// dropping them kept the drift (rendered hills 1: 1.42 % t_err with the map alone, 0.72 % with
// the pairs' vote; docs/benchmark-history.md, "The pairs outvote the map").
//
// A pair measured on a road mask that is taken out is dropped: the mask's road landmarks are
// road too and rarely all wrong together. A pair measured on the region ahead without
// segmentation (RoadPairPlane::on_road_mask false) stays as a reading that votes and comes
// back when enough pairs agree with it: there the sparse road landmarks are whatever stands
// below the horizon, the map's first scale may be far off (rendered highway 3 a quarter of its
// length), and each pair that would correct it comes alone. Returns the pairs taken out.
int ReviewRoadPairs(double camera_height, double max_offset, LocalWindow* window) {
  std::vector<std::pair<Keyframe*, double>> pairs;
  for (Keyframe& keyframe : window->keyframes()) {
    if (!keyframe.road_pair) continue;
    const Keyframe* anchor = window->FindKeyframe(keyframe.road_pair->anchor_frame);
    if (anchor == nullptr) continue;
    const double baseline = (anchor->cam_from_world.inverse().translation() -
                             keyframe.cam_from_world.inverse().translation())
                                .norm();
    pairs.emplace_back(&keyframe, keyframe.road_pair->height_per_baseline * baseline);
  }
  std::vector<double> heights;
  for (const auto& pair : pairs) heights.push_back(pair.second);
  const double median = heights.empty() ? camera_height : Median(heights);
  // The median of readings that all disagree is one of them: only a consensus votes.
  const size_t agreeing =
      static_cast<size_t>(std::count_if(heights.begin(), heights.end(), [&](double h) {
        return std::abs(h - median) <= max_offset;
      }));
  const bool pairs_vote = agreeing >= kMinRoadPairsToOutvoteTheMap;
  int taken_out = 0;
  for (const auto& [keyframe, height] : pairs) {
    RoadPairPlane& pair = *keyframe->road_pair;
    const bool off_the_map = std::abs(height - camera_height) > max_offset;
    const bool off_the_pairs = !pairs_vote || std::abs(height - median) > max_offset;
    const bool in_adjustment = !(off_the_map && off_the_pairs);
    if (pair.in_adjustment && !in_adjustment) ++taken_out;
    pair.in_adjustment = in_adjustment;
    if (!in_adjustment && pair.on_road_mask) keyframe->road_pair.reset();
  }
  return taken_out;
}

// The part of the window each keyframe belongs to, counted from 0: a new part begins at a
// keyframe where no landmark is seen both from a keyframe before it and from it or one after
// it, so that no residual ties the parts together.
std::vector<size_t> UnlinkedParts(const std::map<int64_t, std::pair<size_t, size_t>>& seen_from,
                                  size_t num_keyframes) {
  std::vector<int> spans_starting(num_keyframes + 1, 0);
  for (const auto& [id, span] : seen_from) {
    if (span.first == span.second) continue;
    ++spans_starting[span.first + 1];
    --spans_starting[span.second + 1];
  }
  std::vector<size_t> part(num_keyframes, 0);
  int crossing = 0;
  for (size_t k = 0; k < num_keyframes; ++k) {
    crossing += spans_starting[k];
    if (k > 0) part[k] = part[k - 1] + (crossing == 0 ? 1 : 0);
  }
  return part;
}

}  // namespace

void LocalBundleAdjusterOptions::Check() const {
  CheckOption(max_iterations >= 1, "mapping.ba_max_iterations", "must be >= 1");
  CheckOption(reprojection_loss_px > 0.0, "mapping.ba_reprojection_loss_px", "must be > 0");
  CheckOption(max_reprojection_error_px > 0.0, "mapping.ba_max_reprojection_error_px",
              "must be > 0");
  CheckOption(camera_height_sigma_m > 0.0 && std::isfinite(camera_height_sigma_m),
              "mapping.camera_height_sigma_m", "must be a positive number of metres");
  CheckOption(camera_height_loss > 0.0, "mapping.camera_height_loss", "must be > 0");
  CheckOption(min_road_landmarks >= 3, "mapping.min_road_landmarks",
              "must be >= 3 (a plane needs three points)");
  CheckOption(road_outlier_sigmas > 0.0, "mapping.road_outlier_sigmas", "must be > 0");
  CheckOption(road_pair_sigma_m > 0.0 && std::isfinite(road_pair_sigma_m),
              "mapping.road_pair_sigma_m", "must be a positive number of metres");
}

BundleAdjustmentReport AdjustLocalWindow(const PinholeCamera& camera, double camera_height,
                                         const LocalBundleAdjusterOptions& options,
                                         LocalWindow* window) {
  const auto start = std::chrono::steady_clock::now();
  BundleAdjustmentReport report;
  std::deque<Keyframe>& keyframes = window->keyframes();
  std::map<int64_t, Landmark>& landmarks = window->landmarks();
  report.num_keyframes = static_cast<int>(keyframes.size());
  report.num_landmarks = static_cast<int>(landmarks.size());
  report.num_road_landmarks = window->CountRoadLandmarks();
  if (keyframes.size() < 2 || landmarks.empty()) return report;
  report.num_road_pairs = window->CountRoadPairs();
  report.scale_from_road =
      report.num_road_landmarks >= options.min_road_landmarks || report.num_road_pairs > 0;

  std::vector<PoseParameters> poses;
  poses.reserve(keyframes.size());
  std::map<int, size_t> pose_of_frame;
  for (const Keyframe& keyframe : keyframes) {
    pose_of_frame[keyframe.frame_index] = poses.size();
    poses.push_back(ToPoseParameters(keyframe.cam_from_world));
  }
  std::map<int64_t, Eigen::Vector3d> points;
  for (const auto& [id, landmark] : landmarks) points[id] = landmark.position;

  // One loss object per kind, shared by its residuals and owned here, not by the problem.
  ceres::HuberLoss reprojection_loss(options.reprojection_loss_px);
  ceres::HuberLoss height_loss(options.camera_height_loss);
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  // The first and last keyframe (index) that observes each landmark in the problem.
  std::map<int64_t, std::pair<size_t, size_t>> seen_from;
  for (size_t k = 0; k < keyframes.size(); ++k) {
    for (const auto& [id, pixel] : keyframes[k].observations) {
      const auto point = points.find(id);
      if (point == points.end()) continue;
      // A residual that cannot be evaluated at the start (a landmark behind the camera: a
      // wrong track, or a pose moved by the last adjustment) makes Ceres give up on the whole
      // window; such an observation is left out here and removed with the outliers below.
      if (!std::isfinite(
              ReprojectionError(camera, keyframes[k].cam_from_world, point->second, pixel))) {
        continue;
      }
      problem.AddResidualBlock(ReprojectionResidual::Create(camera, pixel), &reprojection_loss,
                               poses[k].data(), point->second.data());
      const auto [span, first_seen] = seen_from.emplace(id, std::make_pair(k, k));
      if (!first_seen) span->second.second = k;
    }
  }
  for (const auto& [id, landmark] : landmarks) {
    if (!landmark.is_road) continue;
    const auto anchor = pose_of_frame.find(landmark.road_anchor_frame);
    if (anchor == pose_of_frame.end()) continue;
    problem.AddResidualBlock(
        new TwoRowResidual(CameraHeightResidual::Create(
            landmark.road_normal_in_anchor, camera_height, options.camera_height_sigma_m)),
        &height_loss, poses[anchor->second].data(), points[id].data());
  }
  for (size_t k = 0; k < keyframes.size(); ++k) {
    if (!keyframes[k].road_pair || !keyframes[k].road_pair->in_adjustment) continue;
    const auto anchor = pose_of_frame.find(keyframes[k].road_pair->anchor_frame);
    if (anchor == pose_of_frame.end()) continue;
    problem.AddResidualBlock(RoadPairResidual::Create(keyframes[k].road_pair->height_per_baseline,
                                                      camera_height, options.road_pair_sigma_m),
                             &height_loss, poses[anchor->second].data(), poses[k].data());
  }
  // The gauge, in each part of the window (a part begins where no landmark ties a keyframe to
  // the ones before it: every track lost to a black frame, its place only the motion's
  // prediction): the part's oldest keyframe in the problem is held, and the next one too while
  // the part's own road does not set its scale. A keyframe left without residuals is not in
  // the problem, so they are counted among those that are.
  const std::vector<size_t> part = UnlinkedParts(seen_from, keyframes.size());
  std::vector<int> road_landmarks_in_part(part.back() + 1, 0);
  std::vector<bool> road_pair_in_part(part.back() + 1, false);
  for (const auto& [id, landmark] : landmarks) {
    const auto anchor = pose_of_frame.find(landmark.road_anchor_frame);
    if (landmark.is_road && anchor != pose_of_frame.end()) {
      ++road_landmarks_in_part[part[anchor->second]];
    }
  }
  for (size_t k = 0; k < keyframes.size(); ++k) {
    if (keyframes[k].road_pair && keyframes[k].road_pair->in_adjustment &&
        pose_of_frame.count(keyframes[k].road_pair->anchor_frame)) {
      road_pair_in_part[part[k]] = true;
    }
  }
  size_t held_part = 0;
  int held = 0;
  for (size_t k = 0; k < poses.size(); ++k) {
    if (!problem.HasParameterBlock(poses[k].data())) continue;
    if (part[k] != held_part) {
      held_part = part[k];
      held = 0;
    }
    const bool road_scales_part =
        road_landmarks_in_part[part[k]] >= options.min_road_landmarks || road_pair_in_part[part[k]];
    if (held >= (road_scales_part ? 1 : 2)) continue;
    problem.SetParameterBlockConstant(poses[k].data());
    ++held;
  }

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_SCHUR;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.num_threads = 1;  // deterministic, and the pipeline owns the threads
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  report.ran = true;
  report.iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;

  for (size_t k = 0; k < keyframes.size(); ++k) {
    keyframes[k].cam_from_world = FromPoseParameters(poses[k]);
  }
  for (auto& [id, landmark] : landmarks) landmark.position = points[id];

  for (Keyframe& keyframe : keyframes) {
    std::vector<int64_t> rejected;
    for (const auto& [id, pixel] : keyframe.observations) {
      const auto landmark = landmarks.find(id);
      if (landmark == landmarks.end()) continue;
      if (ReprojectionError(camera, keyframe.cam_from_world, landmark->second.position, pixel) >
          options.max_reprojection_error_px) {
        rejected.push_back(id);
      }
    }
    for (int64_t id : rejected) window->RemoveObservation(&keyframe, id);
    report.removed_observations += static_cast<int>(rejected.size());
  }
  if (report.scale_from_road) {
    const double max_offset = options.road_outlier_sigmas * options.camera_height_sigma_m;
    for (auto& [id, landmark] : landmarks) {
      if (!landmark.is_road) continue;
      const Keyframe* anchor = window->FindKeyframe(landmark.road_anchor_frame);
      if (anchor == nullptr) continue;
      const double height =
          landmark.road_normal_in_anchor.dot(anchor->cam_from_world * landmark.position);
      if (std::abs(height - camera_height) > max_offset) {
        landmark.is_road = false;
        ++report.removed_road_marks;
      }
    }
  }
  // Also where every pair is out of the adjustment: they still vote against the map.
  if (report.scale_from_road || window->CountRoadPairReadings() > report.num_road_pairs) {
    report.removed_road_marks += ReviewRoadPairs(
        camera_height, options.road_outlier_sigmas * options.road_pair_sigma_m, window);
  }
  report.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace roadscale
