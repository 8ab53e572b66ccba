#include "roadscale/eval/kitti_odometry_metric.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "roadscale/util/error.h"

#include <Eigen/LU>

// This file must be compiled without fused multiply-add contraction (see CMakeLists.txt):
// the devkit's float path distances round after every product and sum, and one different
// rounding can move a segment's end frame.

namespace roadscale {
namespace {

std::vector<Eigen::Matrix4f> ToFloatPoses(const std::vector<Rigid3d>& poses) {
  std::vector<Eigen::Matrix4f> result;
  result.reserve(poses.size());
  for (const Rigid3d& pose : poses) result.push_back(pose.matrix().cast<float>());
  return result;
}

std::vector<float> PathDistances(const std::vector<Eigen::Matrix4f>& poses) {
  std::vector<float> dist;
  dist.reserve(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    if (i == 0) {
      dist.push_back(0.0f);
      continue;
    }
    const float dx = poses[i - 1](0, 3) - poses[i](0, 3);
    const float dy = poses[i - 1](1, 3) - poses[i](1, 3);
    const float dz = poses[i - 1](2, 3) - poses[i](2, 3);
    dist.push_back(dist.back() + std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return dist;
}

// The first frame at or after `first` whose path distance exceeds dist[first] + length, or
// -1. dist never decreases, so the first such frame is an upper bound.
int LastFrameOfSegment(const std::vector<float>& dist, int first, float length) {
  const float end_distance = dist[first] + length;
  const auto it = std::upper_bound(dist.begin() + first, dist.end(), end_distance);
  return it == dist.end() ? -1 : static_cast<int>(it - dist.begin());
}

}  // namespace

void KittiMetricOptions::Check() const {
  CheckOption(!lengths_m.empty(), "lengths_m", "needs at least one segment length");
  for (size_t i = 0; i < lengths_m.size(); ++i) {
    CheckOption(std::isfinite(lengths_m[i]) && lengths_m[i] > 0.0f, "lengths_m",
                "segment lengths must be positive, got " + std::to_string(lengths_m[i]));
    CheckOption(i == 0 || lengths_m[i] > lengths_m[i - 1], "lengths_m",
                "segment lengths must increase");
  }
  CheckOption(step_frames >= 1, "step_frames",
              "must be at least 1, got " + std::to_string(step_frames));
}

float KittiRotationError(const Eigen::Matrix3f& rotation) {
  // The trace is summed in float, the half-angle cosine formed in double and stored as
  // float, as the devkit's expression does.
  const float trace = rotation(0, 0) + rotation(1, 1) + rotation(2, 2);
  const float cosine = static_cast<float>(0.5 * (static_cast<double>(trace) - 1.0));
  return std::acos(std::max(std::min(cosine, 1.0f), -1.0f));
}

std::vector<float> KittiPathDistances(const std::vector<Rigid3d>& world_from_cam) {
  return PathDistances(ToFloatPoses(world_from_cam));
}

KittiOdometryResult EvaluateKittiOdometry(const std::vector<Rigid3d>& gt_world_from_cam,
                                          const std::vector<Rigid3d>& est_world_from_cam,
                                          const KittiMetricOptions& options) {
  options.Check();
  if (gt_world_from_cam.size() != est_world_from_cam.size()) {
    throw Error("the KITTI metric needs one estimated pose per ground-truth pose: got " +
                std::to_string(est_world_from_cam.size()) + " estimated and " +
                std::to_string(gt_world_from_cam.size()) + " ground-truth poses");
  }
  if (gt_world_from_cam.empty()) throw Error("the KITTI metric needs at least one pose");

  const std::vector<Eigen::Matrix4f> gt = ToFloatPoses(gt_world_from_cam);
  const std::vector<Eigen::Matrix4f> est = ToFloatPoses(est_world_from_cam);
  const std::vector<float> dist = PathDistances(gt);
  const int n = static_cast<int>(gt.size());

  KittiOdometryResult result;
  result.gt_path_length_m = dist.back();
  for (int first = 0; first < n; first += options.step_frames) {
    for (float length : options.lengths_m) {
      const int last = LastFrameOfSegment(dist, first, length);
      if (last < 0) continue;
      const Eigen::Matrix4f gt_delta = gt[first].inverse() * gt[last];
      const Eigen::Matrix4f est_delta = est[first].inverse() * est[last];
      const Eigen::Matrix4f error = est_delta.inverse() * gt_delta;
      const float tx = error(0, 3);
      const float ty = error(1, 3);
      const float tz = error(2, 3);
      KittiSegmentError segment;
      segment.first_frame = first;
      segment.last_frame = last;
      segment.length_m = length;
      segment.t_err = std::sqrt(tx * tx + ty * ty + tz * tz) / length;
      segment.r_err = KittiRotationError(error.topLeftCorner<3, 3>()) / length;
      result.segments.push_back(segment);
    }
  }

  // Float sums in segment order, divided by the float count, as the devkit averages.
  const auto mean = [&](auto selected, auto value) -> std::optional<float> {
    float sum = 0.0f;
    float count = 0.0f;
    for (const KittiSegmentError& segment : result.segments) {
      if (!selected(segment)) continue;
      sum += value(segment);
      count += 1.0f;
    }
    if (count == 0.0f) return std::nullopt;
    return sum / count;
  };
  const auto all = [](const KittiSegmentError&) { return true; };
  const auto t_err = [](const KittiSegmentError& s) { return s.t_err; };
  const auto r_err = [](const KittiSegmentError& s) { return s.r_err; };
  result.t_err = mean(all, t_err);
  result.r_err = mean(all, r_err);
  for (float length : options.lengths_m) {
    const auto of_length = [length](const KittiSegmentError& s) { return s.length_m == length; };
    KittiLengthResult per_length;
    per_length.length_m = length;
    per_length.n_segments =
        static_cast<int>(std::count_if(result.segments.begin(), result.segments.end(), of_length));
    per_length.t_err = mean(of_length, t_err);
    per_length.r_err = mean(of_length, r_err);
    result.per_length.push_back(per_length);
  }
  return result;
}

}  // namespace roadscale
