#include "roadscale/eval/kitti_odometry_metric.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "roadscale/util/error.h"

// The devkit (evaluate_odometry.cpp with its Matrix class) keeps poses, products and
// inverses in double and rounds to float only the path distances and the per-segment errors;
// doing any of the matrix arithmetic in float instead moves r_err by ~1e-4 relative (the
// float acos of a cosine near 1 magnifies every rounding). This file is compiled without
// fused multiply-add contraction (see CMakeLists.txt) and written as plain scalar loops in
// the devkit's order rather than Eigen's vectorised kernels, so that every operation rounds
// as the devkit's does, on every platform.

namespace roadscale {
namespace {

// A 4x4 homogeneous pose, m[row][col].
struct Pose4d {
  double m[4][4];
};

std::vector<Pose4d> ToPoses(const std::vector<Rigid3d>& poses, const char* which) {
  std::vector<Pose4d> result(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        result[i].m[r][c] = poses[i].matrix()(r, c);
        // Float holds the per-segment errors: a pose beyond its range gives inf errors.
        if (!std::isfinite(static_cast<float>(result[i].m[r][c]))) {
          throw Error(std::string("the KITTI metric keeps its errors in single precision, and ") +
                      which + " pose " + std::to_string(i + 1) + " has a value beyond its range");
        }
      }
    }
  }
  return result;
}

Pose4d Multiply(const Pose4d& a, const Pose4d& b) {
  Pose4d c;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += a.m[i][k] * b.m[k][j];
      c.m[i][j] = sum;
    }
  }
  return c;
}

// The general inverse, as the devkit computes it: Gauss-Jordan elimination with full
// pivoting on [pose | I]. Each step takes as pivot the largest |a(r, c)| over the rows and
// columns not pivoted yet (scanning rows, then columns, the last of equal ones), swaps row r
// into row c, scales that row by the pivot's reciprocal and eliminates column c from every
// other row. Pivot rows land on their column's index, so the right half is the inverse
// without unscrambling. General rather than rigid (R^T, -R^T t): files written with few
// digits are not exactly rigid, and the devkit inverts them as they are.
Pose4d Inverse(const Pose4d& pose) {
  Pose4d a = pose;
  Pose4d inverse{};
  for (int i = 0; i < 4; ++i) inverse.m[i][i] = 1.0;
  bool pivoted[4] = {false, false, false, false};
  for (int step = 0; step < 4; ++step) {
    double largest = 0.0;
    int pivot_row = -1;
    int pivot_col = -1;
    for (int r = 0; r < 4; ++r) {
      if (pivoted[r]) continue;
      for (int c = 0; c < 4; ++c) {
        if (!pivoted[c] && std::fabs(a.m[r][c]) >= largest) {
          largest = std::fabs(a.m[r][c]);
          pivot_row = r;
          pivot_col = c;
        }
      }
    }
    // Finite poses that passed the trajectory readers' rotation check never get here.
    if (pivot_row < 0 || !(largest > 0.0)) throw Error("the KITTI metric met a singular pose");
    const int c = pivot_col;
    pivoted[c] = true;
    if (pivot_row != c) {
      std::swap(a.m[pivot_row], a.m[c]);
      std::swap(inverse.m[pivot_row], inverse.m[c]);
    }
    const double reciprocal = 1.0 / a.m[c][c];
    for (int k = 0; k < 4; ++k) {
      a.m[c][k] *= reciprocal;
      inverse.m[c][k] *= reciprocal;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double factor = a.m[r][c];
      for (int k = 0; k < 4; ++k) {
        a.m[r][k] -= a.m[c][k] * factor;
        inverse.m[r][k] -= inverse.m[c][k] * factor;
      }
    }
  }
  return inverse;
}

// The differences are taken in double and stored as float, the sums are float, as the
// devkit's trajectoryDistances does.
std::vector<float> PathDistances(const std::vector<Pose4d>& poses) {
  std::vector<float> dist;
  dist.reserve(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    if (i == 0) {
      dist.push_back(0.0f);
      continue;
    }
    const float dx = static_cast<float>(poses[i - 1].m[0][3] - poses[i].m[0][3]);
    const float dy = static_cast<float>(poses[i - 1].m[1][3] - poses[i].m[1][3]);
    const float dz = static_cast<float>(poses[i - 1].m[2][3] - poses[i].m[2][3]);
    dist.push_back(dist.back() + std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  return dist;
}

// The error pose's diagonal rounded to float, as the devkit's rotationError reads it.
float RotationErrorOf(const Pose4d& error) {
  Eigen::Matrix3f rotation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = static_cast<float>(error.m[r][c]);
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
  return PathDistances(ToPoses(world_from_cam, "a"));
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

  const std::vector<Pose4d> gt = ToPoses(gt_world_from_cam, "ground-truth");
  const std::vector<Pose4d> est = ToPoses(est_world_from_cam, "estimated");
  const std::vector<float> dist = PathDistances(gt);
  const int n = static_cast<int>(gt.size());

  KittiOdometryResult result;
  result.gt_path_length_m = dist.back();
  for (int first = 0; first < n; first += options.step_frames) {
    for (float length : options.lengths_m) {
      const int last = LastFrameOfSegment(dist, first, length);
      if (last < 0) continue;
      const Pose4d gt_delta = Multiply(Inverse(gt[first]), gt[last]);
      const Pose4d est_delta = Multiply(Inverse(est[first]), est[last]);
      const Pose4d error = Multiply(Inverse(est_delta), gt_delta);
      const float tx = static_cast<float>(error.m[0][3]);
      const float ty = static_cast<float>(error.m[1][3]);
      const float tz = static_cast<float>(error.m[2][3]);
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
