#include "roadscale/segmentation/mask_carrying.h"

#include <algorithm>
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
  if (prev.size() != cur.size()) throw Error("road homography: one current pixel per track");
  if (prev_road_mask.empty()) return std::nullopt;
  std::vector<cv::Point2f> from, to;
  for (size_t i = 0; i < prev.size(); ++i) {
    if (!PixelOnMask(prev_road_mask, prev[i])) continue;
    from.emplace_back(static_cast<float>(prev[i].x()), static_cast<float>(prev[i].y()));
    to.emplace_back(static_cast<float>(cur[i].x()), static_cast<float>(cur[i].y()));
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
