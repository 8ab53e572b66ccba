#include "roadscale/scale/road_plane_alignment.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "roadscale/util/error.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace roadscale {
namespace {

// A road normal further than this from the guess is not the road (a wall, a car's side).
constexpr double kMaxNormalChangeDeg = 20.0;

// One pyramid level of both images: grey values and the target image's gradients as float,
// the masks, and the camera at that resolution. The samples come from the source image and
// are warped into the target.
struct Level {
  cv::Mat source;
  cv::Mat target;
  cv::Mat target_dx;
  cv::Mat target_dy;
  cv::Mat source_mask;
  cv::Mat target_mask;  // empty when no target mask was given
  Eigen::Matrix3d K;
};

// A road pixel of the source image: its ray r (z = 1), R r (fixed for the whole alignment,
// so turned once), and its grey value.
struct Sample {
  Eigen::Vector3d ray;
  Eigen::Vector3d rotated;
  float grey = 0.0f;
};

// The warp from the source image into the target: a source road pixel along the ray r lands at
// pi(K w) with w = R r + d (m.r), R = prev_from_cur (target_from_source) and d = -R u, u the
// direction of the translation of source_from_target (in the source frame).
struct WarpState {
  Eigen::Matrix3d prev_from_cur;
  Eigen::Vector3d translation_direction;  // u
  Eigen::Vector3d m;
  double offset = 0.0;  // grey offset of the target against the source

  Eigen::Vector3d Direction() const { return -(prev_from_cur * translation_direction); }
};

float Bilinear(const cv::Mat& image, double x, double y) {
  const int x0 = static_cast<int>(x);
  const int y0 = static_cast<int>(y);
  const float ax = static_cast<float>(x - x0);
  const float ay = static_cast<float>(y - y0);
  const float* row0 = image.ptr<float>(y0) + x0;
  const float* row1 = image.ptr<float>(y0 + 1) + x0;
  return (1.0f - ay) * ((1.0f - ax) * row0[0] + ax * row0[1]) +
         ay * ((1.0f - ax) * row1[0] + ax * row1[1]);
}

Eigen::Matrix3d LevelIntrinsics(const PinholeCamera& camera, int level) {
  // pyrDown maps pixel centre c to (c + 0.5) / 2 - 0.5.
  const double scale = std::ldexp(1.0, -level);
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  K(0, 0) = camera.fx * scale;
  K(1, 1) = camera.fy * scale;
  K(0, 2) = (camera.cx + 0.5) * scale - 0.5;
  K(1, 2) = (camera.cy + 0.5) * scale - 0.5;
  return K;
}

std::vector<Level> BuildLevels(const cv::Mat& source_image, const cv::Mat& target_image,
                               const cv::Mat& source_mask, const cv::Mat& target_mask,
                               const PinholeCamera& camera,
                               const RoadPlaneAlignmentOptions& options) {
  // Into new images: the masks belong to the caller (and to the keyframes that share them).
  cv::Mat source_eroded;
  cv::Mat target_eroded;
  if (options.mask_erosion_px > 0) {
    const int side = 2 * options.mask_erosion_px + 1;
    const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(side, side));
    cv::erode(source_mask, source_eroded, kernel);
    if (!target_mask.empty()) cv::erode(target_mask, target_eroded, kernel);
  } else {
    source_eroded = source_mask;
    target_eroded = target_mask;
  }
  std::vector<Level> levels(options.pyramid_levels + 1);
  source_image.convertTo(levels[0].source, CV_32F);
  target_image.convertTo(levels[0].target, CV_32F);
  levels[0].source_mask = source_eroded;
  levels[0].target_mask = target_eroded;
  for (int l = 0; l <= options.pyramid_levels; ++l) {
    Level& level = levels[l];
    if (l > 0) {
      cv::pyrDown(levels[l - 1].source, level.source);
      cv::pyrDown(levels[l - 1].target, level.target);
      cv::resize(source_eroded, level.source_mask, level.source.size(), 0, 0, cv::INTER_NEAREST);
      if (!target_eroded.empty()) {
        cv::resize(target_eroded, level.target_mask, level.target.size(), 0, 0, cv::INTER_NEAREST);
      }
    }
    cv::Sobel(level.target, level.target_dx, CV_32F, 1, 0, 1, 0.5);
    cv::Sobel(level.target, level.target_dy, CV_32F, 0, 1, 1, 0.5);
    level.K = LevelIntrinsics(camera, l);
  }
  return levels;
}

// Whether the point the ray r (r.z = 1) meets on the plane n.X = 1 (n unit, camera heights)
// lies within the options' limits: sideways along the camera's x axis laid into the plane,
// ahead along its z axis.
bool WithinSampledRegion(const Eigen::Vector3d& ray, const Eigen::Vector3d& normal,
                         const Eigen::Vector3d& sideways,
                         const RoadPlaneAlignmentOptions& options) {
  const double along_normal = normal.dot(ray);
  if (!(along_normal > 0.0)) return false;
  if (options.max_lateral_offset > 0.0 &&
      std::abs(sideways.dot(ray)) > options.max_lateral_offset * along_normal) {
    return false;
  }
  return options.max_distance <= 0.0 || ray.z() <= options.max_distance * along_normal;
}

std::vector<Sample> SelectSamples(const Level& level, const Eigen::Matrix3d& prev_from_cur,
                                  const Eigen::Vector3d& normal, bool within_limits,
                                  const RoadPlaneAlignmentOptions& options) {
  cv::Mat dx, dy;
  cv::Sobel(level.source, dx, CV_32F, 1, 0, 1, 0.5);
  cv::Sobel(level.source, dy, CV_32F, 0, 1, 1, 0.5);
  const float min_squared = static_cast<float>(options.min_gradient * options.min_gradient);
  const Eigen::Matrix3d K_inverse = level.K.inverse();
  const Eigen::Vector3d sideways =
      (Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(normal) * normal).normalized();
  const bool limited =
      within_limits && (options.max_lateral_offset > 0.0 || options.max_distance > 0.0);
  std::vector<cv::Point> textured;
  for (int y = 1; y + 1 < level.source.rows; ++y) {
    const uint8_t* mask = level.source_mask.ptr<uint8_t>(y);
    const float* gx = dx.ptr<float>(y);
    const float* gy = dy.ptr<float>(y);
    for (int x = 1; x + 1 < level.source.cols; ++x) {
      if (mask[x] == 0 || gx[x] * gx[x] + gy[x] * gy[x] < min_squared) continue;
      if (limited &&
          !WithinSampledRegion(K_inverse * Eigen::Vector3d(x, y, 1.0), normal, sideways, options)) {
        continue;
      }
      textured.emplace_back(x, y);
    }
  }
  const double stride = std::max(1.0, static_cast<double>(textured.size()) / options.max_samples);
  std::vector<Sample> samples;
  for (double i = 0.0; i < static_cast<double>(textured.size()); i += stride) {
    const cv::Point& pixel = textured[static_cast<size_t>(i)];
    Sample sample;
    sample.ray = K_inverse * Eigen::Vector3d(pixel.x, pixel.y, 1.0);
    sample.rotated = prev_from_cur * sample.ray;
    sample.grey = level.source.at<float>(pixel);
    samples.push_back(sample);
  }
  return samples;
}

// Where a sample lands in the target image (w = R r + d (m.r), q = K w); false when outside
// the image (with a one-pixel margin for the interpolation) or off the target's road mask.
bool Warp(const Level& level, const Sample& sample, const Eigen::Vector3d& direction,
          const Eigen::Vector3d& m, Eigen::Vector3d* q, double* x, double* y) {
  *q = level.K * (sample.rotated + direction * m.dot(sample.ray));
  if (!(q->z() > 1e-9)) return false;
  *x = q->x() / q->z();
  *y = q->y() / q->z();
  if (!(*x >= 0.0 && *y >= 0.0 && *x < level.target.cols - 1 && *y < level.target.rows - 1)) {
    return false;
  }
  if (!level.target_mask.empty() &&
      level.target_mask.at<uint8_t>(static_cast<int>(*y + 0.5), static_cast<int>(*x + 0.5)) == 0) {
    return false;
  }
  return true;
}

// The robust cost of a grey-level residual and its weight in iteratively reweighted least
// squares (rho'(r) / r), for options.loss.
class GreyLoss {
 public:
  explicit GreyLoss(const RoadPlaneAlignmentOptions& options)
      : tukey_(options.loss == RoadPlaneAlignmentOptions::Loss::kTukey),
        scale_(tukey_ ? options.loss_scale_grey * kTukeyOverHuber : options.loss_scale_grey) {}

  double Cost(double residual) const {
    const double a = std::abs(residual);
    if (!tukey_) return a <= scale_ ? 0.5 * a * a : scale_ * (a - 0.5 * scale_);
    if (a >= scale_) return scale_ * scale_ / 6.0;
    const double u = 1.0 - (a / scale_) * (a / scale_);
    return scale_ * scale_ / 6.0 * (1.0 - u * u * u);
  }

  double Weight(double residual) const {
    const double a = std::abs(residual);
    if (!tukey_) return a <= scale_ ? 1.0 : scale_ / a;
    if (a >= scale_) return 0.0;
    const double u = 1.0 - (a / scale_) * (a / scale_);
    return u * u;
  }

 private:
  // The two losses' tuning constants for 95 % efficiency on Gaussian residuals.
  static constexpr double kTukeyOverHuber = 4.685 / 1.345;
  bool tukey_;
  double scale_;
};

// The best |t| / h on a logarithmic grid between `lowest` and `highest` with the normal and
// the rotation held, each with the median grey offset; requires half of the samples to land
// in the target's road.
std::optional<Eigen::Vector3d> SearchStart(const Level& level, const std::vector<Sample>& samples,
                                           const WarpState& state, const Eigen::Vector3d& normal,
                                           double lowest, double highest,
                                           const RoadPlaneAlignmentOptions& options) {
  std::optional<Eigen::Vector3d> best;
  double best_cost = 0.0;
  const double ratio = highest / lowest;
  const Eigen::Vector3d direction = state.Direction();
  const GreyLoss loss(options);
  std::vector<double> residuals;
  for (int step = 0; step < options.search_steps; ++step) {
    const double fraction = options.search_steps > 1 ? step / (options.search_steps - 1.0) : 0.0;
    const Eigen::Vector3d m = lowest * std::pow(ratio, fraction) * normal;
    residuals.clear();
    for (const Sample& sample : samples) {
      Eigen::Vector3d q;
      double x = 0.0, y = 0.0;
      if (!Warp(level, sample, direction, m, &q, &x, &y)) continue;
      residuals.push_back(Bilinear(level.target, x, y) - sample.grey);
    }
    if (residuals.size() * 2 < samples.size() || residuals.empty()) continue;
    std::nth_element(residuals.begin(), residuals.begin() + residuals.size() / 2, residuals.end());
    const double offset = residuals[residuals.size() / 2];
    double cost = 0.0;
    for (double r : residuals) cost += loss.Cost(r - offset);
    cost /= static_cast<double>(residuals.size());
    if (!best || cost < best_cost) {
      best = m;
      best_cost = cost;
    }
  }
  return best;
}

struct LevelFit {
  bool converged = false;
  int used = 0;
  int iterations = 0;
};

// Moves m into the plane perpendicular to the translation and returns the directions the fit
// may then move in (columns: two for m, the grey offset).
Eigen::Matrix<double, 4, 3> HoldNormalTangentToTravel(WarpState* state) {
  const Eigen::Vector3d u = state->translation_direction;
  state->m -= state->m.dot(u) * u;
  const Eigen::Vector3d along_normal = state->m.normalized();
  Eigen::Matrix<double, 4, 3> free = Eigen::Matrix<double, 4, 3>::Zero();
  free.block<3, 1>(0, 0) = along_normal;
  free.block<3, 1>(0, 1) = u.cross(along_normal);
  free(3, 2) = 1.0;
  return free;
}

// Gauss-Newton with the robust loss's weights at one level on m and the grey offset.
LevelFit FitLevel(const Level& level, const std::vector<Sample>& samples,
                  const RoadPlaneAlignmentOptions& options, WarpState* state) {
  Eigen::Matrix<double, 4, 3> tangent;
  if (options.tangent_to_travel) tangent = HoldNormalTangentToTravel(state);
  const Eigen::Vector3d direction = state->Direction();
  const GreyLoss loss(options);
  LevelFit fit;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
    Eigen::Vector4d g = Eigen::Vector4d::Zero();
    int used = 0;
    for (const Sample& sample : samples) {
      Eigen::Vector3d q;
      double x = 0.0, y = 0.0;
      if (!Warp(level, sample, direction, state->m, &q, &x, &y)) continue;
      const double residual = Bilinear(level.target, x, y) - sample.grey - state->offset;
      const double gx = Bilinear(level.target_dx, x, y);
      const double gy = Bilinear(level.target_dy, x, y);
      // The grey gradient through the projection: d(grey)/dq, then b = K^T that = d(grey)/dw,
      // and w moves by direction (dm.r).
      const Eigen::Vector3d along_q(gx / q.z(), gy / q.z(), -(gx * x + gy * y) / q.z());
      const Eigen::Vector3d b = level.K.transpose() * along_q;
      Eigen::Vector4d J;
      J.head<3>() = b.dot(direction) * sample.ray;
      J(3) = -1.0;
      const double weight = loss.Weight(residual);
      H.noalias() += weight * J * J.transpose();
      g.noalias() += weight * residual * J;
      ++used;
    }
    fit.used = used;
    if (used < 4) return fit;
    ++fit.iterations;
    // A little Levenberg damping keeps a poorly seen direction of m from running off.
    constexpr double kDamping = 1.0 + 1e-4;
    Eigen::Vector4d step;
    if (options.tangent_to_travel) {
      Eigen::Matrix3d reduced = tangent.transpose() * H * tangent;
      reduced.diagonal() *= kDamping;
      step = tangent * reduced.ldlt().solve(-(tangent.transpose() * g));
    } else {
      H.diagonal() *= kDamping;
      step = H.ldlt().solve(-g);
    }
    if (!step.allFinite()) return fit;
    state->m += step.head<3>();
    state->offset += step(3);
    // So strict that a fit sliding along a flat valley of the cost (repeated texture, the
    // wrong minimum) runs out of iterations instead: a stop at 1e-4 let such fits through
    // (bench/road_alignment_accuracy: urban 1 pairs two frames apart, mean error -0.2 % ->
    // +9.5 %).
    if (step.head<3>().norm() < 1e-6 * state->m.norm()) {
      fit.converged = true;
      break;
    }
  }
  return fit;
}

void CheckImage(const cv::Mat& image, const PinholeCamera& camera, const char* what) {
  if (image.type() != CV_8UC1 || image.cols != camera.width || image.rows != camera.height) {
    throw Error(std::string("AlignRoadPlane: ") + what + " must be CV_8UC1 of the camera's size");
  }
}

}  // namespace

void RoadPlaneAlignmentOptions::Check() const {
  CheckOption(pyramid_levels >= 0 && pyramid_levels <= 6, "road_alignment.pyramid_levels",
              "must be 0..6");
  CheckOption(std::isfinite(min_gradient) && min_gradient >= 0.0, "road_alignment.min_gradient",
              "must be >= 0 grey levels per pixel");
  CheckOption(max_samples >= 10, "road_alignment.max_samples", "must be at least 10");
  CheckOption(min_samples >= 4 && min_samples <= max_samples, "road_alignment.min_samples",
              "must be 4..max_samples");
  CheckOption(max_iterations >= 1, "road_alignment.max_iterations", "must be at least 1");
  CheckOption(std::isfinite(loss_scale_grey) && loss_scale_grey > 0.0,
              "road_alignment.loss_scale_grey", "must be a positive number of grey levels");
  CheckOption(std::isfinite(min_baseline_over_height) && min_baseline_over_height > 0.0 &&
                  std::isfinite(max_baseline_over_height) &&
                  max_baseline_over_height > min_baseline_over_height,
              "road_alignment.max_baseline_over_height",
              "needs 0 < min_baseline_over_height < max_baseline_over_height");
  CheckOption(search_steps >= 1, "road_alignment.search_steps", "must be at least 1");
  CheckOption(std::isfinite(expected_search_factor) && expected_search_factor > 1.0,
              "road_alignment.expected_search_factor", "must be > 1");
  CheckOption(mask_erosion_px >= 0, "road_alignment.mask_erosion_px", "must be >= 0 pixels");
  CheckOption(std::isfinite(max_lateral_offset) && max_lateral_offset >= 0.0,
              "road_alignment.max_lateral_offset", "must be >= 0 camera heights (0: no limit)");
  CheckOption(std::isfinite(max_pitch_to_travel_deg) && max_pitch_to_travel_deg >= 0.0,
              "road_alignment.max_pitch_to_travel_deg", "must be >= 0 degrees (0: no limit)");
  CheckOption(std::isfinite(max_distance) && max_distance >= 0.0, "road_alignment.max_distance",
              "must be >= 0 camera heights (0: no limit)");
}

namespace {

void CheckAlignmentInputs(const cv::Mat& prev_image, const cv::Mat& cur_image,
                          const cv::Mat& prev_road_mask, const cv::Mat& cur_road_mask,
                          const PinholeCamera& camera, const RoadPlaneAlignmentOptions& options) {
  options.Check();
  CheckImage(prev_image, camera, "the previous image");
  CheckImage(cur_image, camera, "the current image");
  CheckImage(cur_road_mask, camera, "the current road mask");
  if (!prev_road_mask.empty()) CheckImage(prev_road_mask, camera, "the previous road mask");
}

bool HasMotionAndNormal(const Rigid3d& cur_from_prev, const Eigen::Vector3d& normal_guess) {
  return cur_from_prev.translation().norm() > 0.0 && normal_guess.norm() > 0.0;
}

// The alignment on pyramids already built, from a search near `expected_baseline_over_height`
// (0: over the whole range).
RoadPlaneAlignment AlignOnLevels(const std::vector<Level>& levels, const Rigid3d& cur_from_prev,
                                 const Eigen::Vector3d& normal_guess,
                                 double expected_baseline_over_height,
                                 const RoadPlaneAlignmentOptions& options) {
  RoadPlaneAlignment result;
  // The current road pixels warped into the previous image: X_prev = R^T (X_cur - t), and on
  // the plane n_cur.X_cur = h_cur that is R^T (I - t n_cur^T / h_cur) X_cur, linear in
  // m = |t| n_cur / h_cur again. Driving forward, all of the road the current image sees was
  // in view before, while the previous image's nearest road has left the current one.
  const Eigen::Vector3d u = cur_from_prev.translation().normalized();
  const Eigen::Vector3d normal_in_cur = cur_from_prev.linear() * normal_guess.normalized();

  WarpState state;
  state.prev_from_cur = cur_from_prev.linear().transpose();
  state.translation_direction = u;
  bool started = false;
  bool converged = false;
  for (int l = options.pyramid_levels; l >= 0; --l) {
    const Level& level = levels[l];
    const std::vector<Sample> samples =
        SelectSamples(level, state.prev_from_cur, normal_in_cur, l == 0, options);
    if (!started) {
      const bool expected = expected_baseline_over_height > 0.0;
      const std::optional<Eigen::Vector3d> start =
          SearchStart(level, samples, state, normal_in_cur,
                      expected ? expected_baseline_over_height / options.expected_search_factor
                               : options.min_baseline_over_height,
                      expected ? expected_baseline_over_height * options.expected_search_factor
                               : options.max_baseline_over_height,
                      options);
      if (!start) continue;
      state.m = *start;
      started = true;
    }
    const LevelFit fit = FitLevel(level, samples, options, &state);
    result.iterations += fit.iterations;
    if (l == 0) {
      converged = fit.converged;
      result.samples = fit.used;
    }
  }
  if (!started || result.samples < options.min_samples || !(state.m.norm() > 0.0)) return result;
  // Back to the previous camera: n_prev = R^T n_cur, h_prev = h_cur - n_cur.t (units of |t|).
  const Eigen::Vector3d n_cur = state.m.normalized();
  result.plane.normal = state.prev_from_cur * n_cur;
  result.plane.height = 1.0 / state.m.norm() - n_cur.dot(u);
  const double change_deg =
      std::acos(std::clamp(result.plane.normal.dot(normal_guess.normalized()), -1.0, 1.0)) * 180.0 /
      M_PI;
  result.pitch_to_travel_deg = std::asin(std::min(1.0, std::abs(n_cur.dot(u)))) * 180.0 / M_PI;
  result.ok = converged && result.plane.height > 0.0 && change_deg <= kMaxNormalChangeDeg &&
              (options.max_pitch_to_travel_deg <= 0.0 ||
               result.pitch_to_travel_deg <= options.max_pitch_to_travel_deg);
  return result;
}

}  // namespace

RoadPlaneAlignment AlignRoadPlane(const cv::Mat& prev_image, const cv::Mat& cur_image,
                                  const cv::Mat& prev_road_mask, const cv::Mat& cur_road_mask,
                                  const PinholeCamera& camera, const Rigid3d& cur_from_prev,
                                  const Eigen::Vector3d& normal_guess,
                                  double expected_baseline_over_height,
                                  const RoadPlaneAlignmentOptions& options) {
  CheckAlignmentInputs(prev_image, cur_image, prev_road_mask, cur_road_mask, camera, options);
  if (!HasMotionAndNormal(cur_from_prev, normal_guess)) return RoadPlaneAlignment();
  const std::vector<Level> levels =
      BuildLevels(cur_image, prev_image, cur_road_mask, prev_road_mask, camera, options);
  return AlignOnLevels(levels, cur_from_prev, normal_guess, expected_baseline_over_height, options);
}

RoadPlaneAlignment AlignRoadPlaneOrSearchAll(
    const cv::Mat& prev_image, const cv::Mat& cur_image, const cv::Mat& prev_road_mask,
    const cv::Mat& cur_road_mask, const PinholeCamera& camera, const Rigid3d& cur_from_prev,
    const Eigen::Vector3d& normal_guess, double expected_baseline_over_height,
    const RoadPlaneAlignmentOptions& options) {
  CheckAlignmentInputs(prev_image, cur_image, prev_road_mask, cur_road_mask, camera, options);
  if (!HasMotionAndNormal(cur_from_prev, normal_guess)) return RoadPlaneAlignment();
  // One pyramid serves both searches.
  const std::vector<Level> levels =
      BuildLevels(cur_image, prev_image, cur_road_mask, prev_road_mask, camera, options);
  const RoadPlaneAlignment near_expected =
      AlignOnLevels(levels, cur_from_prev, normal_guess, expected_baseline_over_height, options);
  if (near_expected.ok || !(expected_baseline_over_height > 0.0)) return near_expected;
  return AlignOnLevels(levels, cur_from_prev, normal_guess, 0.0, options);
}

cv::Mat RoadRegionAhead(const PinholeCamera& camera, double max_distance, double half_width) {
  if (!(max_distance > 0.0) || !(half_width > 0.0)) {
    throw Error("RoadRegionAhead: the distance and the half width must be positive");
  }
  cv::Mat region(camera.height, camera.width, CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < region.rows; ++y) {
    uint8_t* row = region.ptr<uint8_t>(y);
    for (int x = 0; x < region.cols; ++x) {
      // The ray (r.x, r.y, 1) meets y = h at the distance h / r.y, r.x h / r.y to the side.
      const Eigen::Vector3d ray = camera.Unproject(Eigen::Vector2d(x, y));
      if (ray.y() * max_distance >= 1.0 && std::abs(ray.x()) <= half_width * ray.y()) row[x] = 255;
    }
  }
  return region;
}

}  // namespace roadscale
