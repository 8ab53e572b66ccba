#include "roadscale/segmentation/mask_carrying.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// Width of the strips a moving-object mask is cut into, each moved on its own.
constexpr int kStripWidthPx = 16;

cv::Matx33d ToCvMatrix(const Eigen::Matrix3d& m) {
  cv::Matx33d out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out(r, c) = m(r, c);
  }
  return out;
}

// Moves one piece of a moving-object mask (its pixels `piece` at `rect`) as the road under the
// middle of its lowest row moves, scaled by the road's horizontal magnification there (an
// upright object's width scales as the road's at its base; the vertical magnification is that
// of the ground, squared), and adds it to `out`.
void CarryPiece(const cv::Mat& piece, const cv::Rect& rect, const Eigen::Matrix3d& cur_from_src,
                const cv::Rect& image, cv::Mat* out) {
  const Eigen::Vector2d base(rect.x + 0.5 * (rect.width - 1), rect.y + rect.height - 1);
  const Eigen::Vector3d mapped = cur_from_src * base.homogeneous();
  double scale = 1.0;
  Eigen::Vector2d moved = base;
  // A base the homography cannot map (above the horizon: not on the road) stays in place.
  if (mapped.z() > 1e-9) {
    moved = mapped.hnormalized();
    const Eigen::Vector3d h0 = cur_from_src.row(0);
    const Eigen::Vector3d h2 = cur_from_src.row(2);
    const Eigen::Vector3d h1 = cur_from_src.row(1);
    const Eigen::Vector2d d_dx((h0(0) - moved.x() * h2(0)) / mapped.z(),
                               (h1(0) - moved.y() * h2(0)) / mapped.z());
    scale = std::clamp(d_dx.norm(), 0.5, 2.0);
  }
  // p' = moved + scale (p - base), in the piece's box and in the destination box.
  const double left = moved.x() - scale * (base.x() - rect.x);
  const double top = moved.y() - scale * (base.y() - rect.y);
  const cv::Rect destination =
      cv::Rect(cv::Point(static_cast<int>(std::floor(left)), static_cast<int>(std::floor(top))),
               cv::Point(static_cast<int>(std::ceil(left + scale * rect.width)) + 1,
                         static_cast<int>(std::ceil(top + scale * rect.height)) + 1)) &
      image;
  if (destination.empty()) return;
  const cv::Matx23d affine(scale, 0.0, left - destination.x, 0.0, scale, top - destination.y);
  cv::Mat warped;
  cv::warpAffine(piece, warped, affine, destination.size(), cv::INTER_NEAREST, cv::BORDER_CONSTANT,
                 cv::Scalar(0));
  (*out)(destination) |= warped;
}

// The tracks whose previous pixel lies on the road mask.
void RoadTracks(const std::vector<Eigen::Vector2d>& prev, const std::vector<Eigen::Vector2d>& cur,
                const cv::Mat& prev_road_mask, std::vector<Eigen::Vector2d>* road_prev,
                std::vector<Eigen::Vector2d>* road_cur) {
  if (prev.size() != cur.size()) throw Error("road homography: one current pixel per track");
  for (size_t i = 0; i < prev.size(); ++i) {
    if (!PixelOnMask(prev_road_mask, prev[i])) continue;
    road_prev->push_back(prev[i]);
    road_cur->push_back(cur[i]);
  }
}

// K exp([omega]x) R (I - s d n^T) K^-1 of FitRoadHomographyOnMotion.
struct PlaneMotionModel {
  Eigen::Matrix3d intrinsics;
  Eigen::Matrix3d inverse_intrinsics;  // computed once: every candidate and iteration needs it
  Eigen::Matrix3d rotation;
  Eigen::Vector3d direction;
  Eigen::Vector3d normal;

  // params: s, then the rotation correction's angle-axis vector.
  Eigen::Matrix3d Homography(const Eigen::Vector4d& params) const {
    const Eigen::Vector3d omega = params.tail<3>();
    const double angle = omega.norm();
    const Eigen::Matrix3d correction =
        angle > 0.0 ? Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix()
                    : Eigen::Matrix3d::Identity();
    return intrinsics * correction * rotation *
           (Eigen::Matrix3d::Identity() - params(0) * direction * normal.transpose()) *
           inverse_intrinsics;
  }
};

Eigen::Vector2d Misfit(const Eigen::Matrix3d& homography, const Eigen::Vector2d& prev,
                       const Eigen::Vector2d& cur) {
  const Eigen::Vector3d mapped = homography * prev.homogeneous();
  if (!(mapped.z() > 1e-9)) return Eigen::Vector2d::Constant(1e9);
  return mapped.hnormalized() - cur;
}

int CountWithin(const Eigen::Matrix3d& homography, const std::vector<Eigen::Vector2d>& prev,
                const std::vector<Eigen::Vector2d>& cur, double threshold,
                std::vector<int>* inliers) {
  if (inliers != nullptr) inliers->clear();
  int count = 0;
  for (size_t i = 0; i < prev.size(); ++i) {
    if (Misfit(homography, prev[i], cur[i]).norm() >= threshold) continue;
    ++count;
    if (inliers != nullptr) inliers->push_back(static_cast<int>(i));
  }
  return count;
}

// Gauss-Newton on the model's four parameters over the tracks `use`, each row weighted by
// Huber's loss at `huber_px`; numeric derivatives (the model is four numbers).
Eigen::Vector4d Refine(const PlaneMotionModel& model, Eigen::Vector4d params,
                       const std::vector<Eigen::Vector2d>& prev,
                       const std::vector<Eigen::Vector2d>& cur, const std::vector<int>& use,
                       double huber_px) {
  constexpr int kIterations = 5;
  constexpr double kStep = 1e-6;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    const Eigen::Matrix3d homography = model.Homography(params);
    std::array<Eigen::Matrix3d, 4> moved;
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector4d shifted = params;
      shifted(k) += kStep;
      moved[k] = model.Homography(shifted);
    }
    Eigen::Matrix4d normal_matrix = Eigen::Matrix4d::Zero();
    Eigen::Vector4d gradient = Eigen::Vector4d::Zero();
    for (int i : use) {
      const Eigen::Vector2d misfit = Misfit(homography, prev[i], cur[i]);
      const double norm = misfit.norm();
      const double weight = norm <= huber_px ? 1.0 : huber_px / norm;
      Eigen::Matrix<double, 2, 4> jacobian;
      for (int k = 0; k < 4; ++k) {
        jacobian.col(k) = (Misfit(moved[k], prev[i], cur[i]) - misfit) / kStep;
      }
      normal_matrix += weight * jacobian.transpose() * jacobian;
      gradient += weight * jacobian.transpose() * misfit;
    }
    const Eigen::Vector4d update = normal_matrix.ldlt().solve(-gradient);
    if (!update.allFinite()) break;
    params += update;
  }
  return params;
}

}  // namespace

void MaskCarryOptions::Check() const {
  CheckOption(road_min_tracks >= 4, "segmentation.carry_road_min_tracks",
              "must be >= 4 (a homography needs 4 points)");
  CheckOption(std::isfinite(road_ransac_threshold_px) && road_ransac_threshold_px > 0.0,
              "segmentation.carry_road_ransac_threshold_px", "must be > 0");
  CheckOption(std::isfinite(dynamic_growth_px_per_frame) && dynamic_growth_px_per_frame >= 0.0,
              "segmentation.carry_dynamic_growth_px_per_frame", "must be >= 0");
}

std::optional<Eigen::Matrix3d> FitRoadHomography(const std::vector<Eigen::Vector2d>& prev,
                                                 const std::vector<Eigen::Vector2d>& cur,
                                                 const cv::Mat& prev_road_mask,
                                                 const MaskCarryOptions& options) {
  if (prev_road_mask.empty()) return std::nullopt;
  std::vector<Eigen::Vector2d> road_prev, road_cur;
  RoadTracks(prev, cur, prev_road_mask, &road_prev, &road_cur);
  std::vector<cv::Point2f> from, to;
  for (size_t i = 0; i < road_prev.size(); ++i) {
    from.emplace_back(static_cast<float>(road_prev[i].x()), static_cast<float>(road_prev[i].y()));
    to.emplace_back(static_cast<float>(road_cur[i].x()), static_cast<float>(road_cur[i].y()));
  }
  if (static_cast<int>(from.size()) < options.road_min_tracks) return std::nullopt;
  // OpenCV's RANSAC draws from a generator with a fixed seed: the same tracks give the same fit.
  std::vector<unsigned char> inliers;
  const cv::Mat h = cv::findHomography(from, to, cv::RANSAC, options.road_ransac_threshold_px,
                                       inliers, 2000, 0.995);
  if (h.empty() || cv::countNonZero(inliers) < options.road_min_tracks) return std::nullopt;
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out(r, c) = h.at<double>(r, c);
  }
  if (!out.allFinite() || std::abs(out(2, 2)) < 1e-12) return std::nullopt;
  return out / out(2, 2);
}

std::optional<Eigen::Matrix3d> FitRoadHomographyOnMotion(
    const std::vector<Eigen::Vector2d>& prev, const std::vector<Eigen::Vector2d>& cur,
    const cv::Mat& prev_road_mask, const Eigen::Matrix3d& intrinsics,
    const Eigen::Matrix3d& rotation, const Eigen::Vector3d& direction,
    const Eigen::Vector3d& normal, const MaskCarryOptions& options) {
  if (prev_road_mask.empty()) return std::nullopt;
  std::vector<Eigen::Vector2d> road_prev, road_cur;
  RoadTracks(prev, cur, prev_road_mask, &road_prev, &road_cur);
  if (static_cast<int>(road_prev.size()) < options.road_min_tracks) return std::nullopt;
  const PlaneMotionModel model{intrinsics, intrinsics.inverse(), rotation, direction, normal};
  // Each track's own s with the predicted rotation (a line's least squares: the mapped pixel
  // is the projection of a - s b), then the s that the most tracks agree with, within a band
  // wide enough for the prediction's rotation error, which the refinement then takes out.
  const double threshold = options.road_ransac_threshold_px;
  const double wide = 3.0 * threshold;
  Eigen::Vector4d best = Eigen::Vector4d::Zero();
  int best_count = -1;
  for (size_t i = 0; i < road_prev.size(); ++i) {
    const Eigen::Vector3d ray = model.inverse_intrinsics * road_prev[i].homogeneous();
    const Eigen::Vector3d a = intrinsics * rotation * ray;
    const Eigen::Vector3d b = intrinsics * rotation * direction * normal.dot(ray);
    const Eigen::Vector2d& p = road_cur[i];
    const Eigen::Vector2d along(b.x() - p.x() * b.z(), b.y() - p.y() * b.z());
    const Eigen::Vector2d offset(a.x() - p.x() * a.z(), a.y() - p.y() * a.z());
    if (!(along.squaredNorm() > 1e-12)) continue;
    Eigen::Vector4d candidate = Eigen::Vector4d::Zero();
    candidate(0) = offset.dot(along) / along.squaredNorm();
    const int count = CountWithin(model.Homography(candidate), road_prev, road_cur, wide, nullptr);
    if (count > best_count) {
      best_count = count;
      best = candidate;
    }
  }
  if (best_count < options.road_min_tracks) return std::nullopt;
  std::vector<int> inliers;
  CountWithin(model.Homography(best), road_prev, road_cur, wide, &inliers);
  Eigen::Vector4d params = Refine(model, best, road_prev, road_cur, inliers, threshold);
  if (CountWithin(model.Homography(params), road_prev, road_cur, threshold, &inliers) <
      options.road_min_tracks) {
    return std::nullopt;
  }
  params = Refine(model, params, road_prev, road_cur, inliers, threshold);
  Eigen::Matrix3d homography = model.Homography(params);
  if (!homography.allFinite() || std::abs(homography(2, 2)) < 1e-12) return std::nullopt;
  return homography / homography(2, 2);
}

cv::Mat CarryRoadMask(const cv::Mat& road_mask, const Eigen::Matrix3d& cur_from_src) {
  if (road_mask.empty()) return cv::Mat();
  cv::Mat out(road_mask.size(), CV_8UC1, cv::Scalar(0));
  // Only where the source's road can land: the road covers the lower part of a frame, and
  // warping the whole frame costs 4 ms.
  const cv::Rect source = cv::boundingRect(road_mask);
  if (source.empty()) return out;
  cv::Rect target(0, 0, road_mask.cols, road_mask.rows);
  std::vector<cv::Point2f> corners;
  for (const auto& [x, y] : {std::pair{source.x, source.y},
                             {source.x + source.width, source.y},
                             {source.x, source.y + source.height},
                             {source.x + source.width, source.y + source.height}}) {
    const Eigen::Vector3d p = cur_from_src * Eigen::Vector3d(x, y, 1.0);
    if (!(p.z() > 1e-9)) {
      corners.clear();
      break;
    }
    corners.emplace_back(static_cast<float>(p.x() / p.z()), static_cast<float>(p.y() / p.z()));
  }
  if (!corners.empty()) {
    target &= cv::boundingRect(corners) + cv::Size(2, 2) - cv::Point(1, 1);
    if (target.empty()) return out;
  }
  Eigen::Matrix3d roi_from_src = cur_from_src;
  roi_from_src.row(0) -= target.x * cur_from_src.row(2);
  roi_from_src.row(1) -= target.y * cur_from_src.row(2);
  cv::Mat warped;
  cv::warpPerspective(road_mask, warped, ToCvMatrix(roi_from_src), target.size(), cv::INTER_NEAREST,
                      cv::BORDER_CONSTANT, cv::Scalar(0));
  warped.copyTo(out(target));
  return out;
}

cv::Mat CarryDynamicMask(const cv::Mat& dynamic_mask, const Eigen::Matrix3d& cur_from_src,
                         int frames, const MaskCarryOptions& options) {
  if (dynamic_mask.empty()) return cv::Mat();
  // At half resolution, a half-resolution pixel set where any of its four is: a quarter of the
  // cost (7 ms a KITTI frame at full resolution), and the masks are coarser than that anyway
  // (the network's 512x256 output, dilated by 5 px).
  cv::Mat half;
  cv::resize(dynamic_mask, half, cv::Size((dynamic_mask.cols + 1) / 2, (dynamic_mask.rows + 1) / 2),
             0.0, 0.0, cv::INTER_AREA);
  half = half > 0;
  // Half-resolution pixel centres: x_half = x / 2 - 1/4.
  Eigen::Matrix3d half_from_full;
  half_from_full << 0.5, 0.0, -0.25, 0.0, 0.5, -0.25, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d half_homography = half_from_full * cur_from_src * half_from_full.inverse();
  cv::Mat out =
      options.dynamic_in_place ? half.clone() : cv::Mat(half.size(), CV_8UC1, cv::Scalar(0));
  const cv::Rect image(0, 0, half.cols, half.rows);
  // Parked cars along a street merge into one blob spanning many depths: each narrow strip of
  // the mask moves with the road under its own lowest pixel.
  for (int x0 = 0; x0 < half.cols; x0 += kStripWidthPx / 2) {
    const cv::Rect strip_rect(x0, 0, std::min(kStripWidthPx / 2, half.cols - x0), half.rows);
    const cv::Rect occupied = cv::boundingRect(half(strip_rect)) + strip_rect.tl();
    if (occupied.empty()) continue;
    cv::Mat labels, stats, centroids;
    const int count =
        cv::connectedComponentsWithStats(half(occupied), labels, stats, centroids, 8, CV_32S);
    for (int i = 1; i < count; ++i) {
      const cv::Rect box(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                         stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
      CarryPiece(labels(box) == i, box + occupied.tl(), half_homography, image, &out);
    }
  }
  const int radius =
      static_cast<int>(std::ceil(0.5 * options.dynamic_growth_px_per_frame * frames - 1e-9));
  if (radius > 0) {
    cv::dilate(out, out,
               cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * radius + 1, 2 * radius + 1)));
  }
  cv::Mat full;
  cv::resize(out, full, dynamic_mask.size(), 0.0, 0.0, cv::INTER_NEAREST);
  return full;
}

}  // namespace roadscale
