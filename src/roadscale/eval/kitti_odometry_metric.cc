#include "roadscale/eval/kitti_odometry_metric.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "roadscale/util/error.h"

// This file must be compiled without fused multiply-add contraction (see CMakeLists.txt),
// and its float arithmetic is written as plain scalar loops rather than Eigen's vectorised
// (and, with FMA available, fused) kernels: every product and sum rounds to float on its
// own, in a fixed order, on every platform. The devkit's path distances decide segment
// ends, and its r_err is dominated by the float acos of cosines near 1, so both are
// sensitive to the rounding of single operations.

namespace roadscale {
namespace {

// A 4x4 homogeneous pose in single precision, m[row][col].
struct Pose4f {
  float m[4][4];
};

Pose4f ToFloat(const Rigid3d& pose, const char* which, size_t index) {
  Pose4f result;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      result.m[r][c] = static_cast<float>(pose.matrix()(r, c));
      if (!std::isfinite(result.m[r][c])) {
        throw Error(std::string("the KITTI metric computes in single precision, and ") + which +
                    " pose " + std::to_string(index + 1) + " has a value beyond its range");
      }
    }
  }
  return result;
}

std::vector<Pose4f> ToFloatPoses(const std::vector<Rigid3d>& poses, const char* which) {
  std::vector<Pose4f> result;
  result.reserve(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) result.push_back(ToFloat(poses[i], which, i));
  return result;
}

Pose4f Multiply(const Pose4f& a, const Pose4f& b) {
  Pose4f c;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      float sum = 0.0f;
      for (int k = 0; k < 4; ++k) sum += a.m[i][k] * b.m[k][j];
      c.m[i][j] = sum;
    }
  }
  return c;
}

// The general inverse by Gauss-Jordan elimination with partial pivoting, in float. General
// rather than rigid (R^T, -R^T t): estimates written with few digits are not exactly rigid,
// and the devkit inverts them as general matrices.
Pose4f Inverse(const Pose4f& pose) {
  Pose4f a = pose;
  Pose4f inverse{};
  for (int i = 0; i < 4; ++i) inverse.m[i][i] = 1.0f;
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 4; ++row) {
      if (std::fabs(a.m[row][col]) > std::fabs(a.m[pivot][col])) pivot = row;
    }
    std::swap(a.m[col], a.m[pivot]);
    std::swap(inverse.m[col], inverse.m[pivot]);
    const float diagonal = a.m[col][col];
    for (int k = 0; k < 4; ++k) {
      a.m[col][k] /= diagonal;
      inverse.m[col][k] /= diagonal;
    }
    for (int row = 0; row < 4; ++row) {
      if (row == col) continue;
      const float factor = a.m[row][col];
      for (int k = 0; k < 4; ++k) {
        a.m[row][k] -= factor * a.m[col][k];
        inverse.m[row][k] -= factor * inverse.m[col][k];
      }
    }
  }
  return inverse;
}

std::vector<float> PathDistances(const std::vector<Pose4f>& poses) {
  std::vector<float> dist;
  dist.reserve(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    if (i == 0) {
      dist.push_back(0.0f);
      continue;
    }
    const float dx = poses[i - 1].m[0][3] - poses[i].m[0][3];
    const float dy = poses[i - 1].m[1][3] - poses[i].m[1][3];
    const float dz = poses[i - 1].m[2][3] - poses[i].m[2][3];
    dist.push_back(dist.back() + std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return dist;
}

float RotationErrorOf(const Pose4f& error) {
  Eigen::Matrix3f rotation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = error.m[r][c];
  }
  return KittiRotationError(rotation);
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
  return PathDistances(ToFloatPoses(world_from_cam, "a"));
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

  const std::vector<Pose4f> gt = ToFloatPoses(gt_world_from_cam, "ground-truth");
  const std::vector<Pose4f> est = ToFloatPoses(est_world_from_cam, "estimated");
  const std::vector<float> dist = PathDistances(gt);
  const int n = static_cast<int>(gt.size());

  KittiOdometryResult result;
  result.gt_path_length_m = dist.back();
  for (int first = 0; first < n; first += options.step_frames) {
    for (float length : options.lengths_m) {
      const int last = LastFrameOfSegment(dist, first, length);
      if (last < 0) continue;
      const Pose4f gt_delta = Multiply(Inverse(gt[first]), gt[last]);
      const Pose4f est_delta = Multiply(Inverse(est[first]), est[last]);
      const Pose4f error = Multiply(Inverse(est_delta), gt_delta);
      const float tx = error.m[0][3];
      const float ty = error.m[1][3];
      const float tz = error.m[2][3];
      KittiSegmentError segment;
      segment.first_frame = first;
      segment.last_frame = last;
      segment.length_m = length;
      segment.t_err = std::sqrt(tx * tx + ty * ty + tz * tz) / length;
      segment.r_err = RotationErrorOf(error) / length;
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
