#include "roadscale/frontend/feature_detector.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <opencv2/imgproc.hpp>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

cv::Ptr<cv::Feature2D> CreateDetector(const FeatureDetectorOptions& options) {
  switch (options.type) {
    case DetectorType::kSift:
      return cv::SIFT::create(/*nfeatures=*/0, /*nOctaveLayers=*/3,
                              options.sift_contrast_threshold);
    case DetectorType::kOrb:
      // ORB keeps only its `nfeatures` best; the grid does the selection here, so ask for many.
      return cv::ORB::create(/*nfeatures=*/20000, /*scaleFactor=*/1.2f, /*nlevels=*/8,
                             /*edgeThreshold=*/31, /*firstLevel=*/0, /*WTA_K=*/2,
                             cv::ORB::HARRIS_SCORE, /*patchSize=*/31, options.corner_threshold);
    case DetectorType::kBrisk:
      return cv::BRISK::create(options.corner_threshold);
    case DetectorType::kAkaze:
      return cv::AKAZE::create();
    case DetectorType::kFast:
      return cv::FastFeatureDetector::create(options.corner_threshold, /*nonmaxSuppression=*/true);
  }
  throw Error("unknown detector type");
}

// Points binned into square cells of the minimum distance, so that "is anything within d?"
// looks at 3x3 cells only.
class NeighbourGrid {
 public:
  explicit NeighbourGrid(double distance) : distance_(distance) {}

  bool HasNeighbour(const cv::Point2f& p) const {
    if (distance_ <= 0.0) return false;
    const int cx = CellOf(p.x);
    const int cy = CellOf(p.y);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find(Key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (const cv::Point2f& q : it->second) {
          const double ex = p.x - q.x;
          const double ey = p.y - q.y;
          if (ex * ex + ey * ey < distance_ * distance_) return true;
        }
      }
    }
    return false;
  }

  void Add(const cv::Point2f& p) {
    if (distance_ > 0.0) cells_[Key(CellOf(p.x), CellOf(p.y))].push_back(p);
  }

 private:
  int CellOf(float v) const { return static_cast<int>(std::floor(v / distance_)); }
  static long long Key(int x, int y) {
    return (static_cast<long long>(x) << 32) ^ static_cast<unsigned int>(y);
  }

  double distance_;
  std::unordered_map<long long, std::vector<cv::Point2f>> cells_;
};

}  // namespace

DetectorType ParseDetectorType(const std::string& name) {
  if (name == "sift") return DetectorType::kSift;
  if (name == "orb") return DetectorType::kOrb;
  if (name == "brisk") return DetectorType::kBrisk;
  if (name == "akaze") return DetectorType::kAkaze;
  if (name == "fast") return DetectorType::kFast;
  throw Error("unknown detector '" + name + "': expected sift, orb, brisk, akaze or fast");
}

std::string DetectorTypeName(DetectorType type) {
  switch (type) {
    case DetectorType::kSift:
      return "sift";
    case DetectorType::kOrb:
      return "orb";
    case DetectorType::kBrisk:
      return "brisk";
    case DetectorType::kAkaze:
      return "akaze";
    case DetectorType::kFast:
      return "fast";
  }
  return "unknown";
}

void FeatureDetectorOptions::Check() const {
  CheckOption(cell_size_px >= 4, "frontend.cell_size_px", "must be at least 4 pixels");
  CheckOption(max_per_cell >= 1, "frontend.max_per_cell", "must be at least 1");
  CheckOption(road_max_per_cell >= 1, "frontend.road_max_per_cell", "must be at least 1");
  CheckOption(std::isfinite(min_distance_px) && min_distance_px >= 0.0, "frontend.min_distance_px",
              "must be a non-negative number");
  CheckOption(border_px >= 0, "frontend.border_px", "must be non-negative");
  CheckOption(std::isfinite(sift_contrast_threshold) && sift_contrast_threshold > 0.0,
              "frontend.sift_contrast_threshold", "must be a positive number");
  CheckOption(corner_threshold >= 1 && corner_threshold <= 255, "frontend.corner_threshold",
              "must be in 1..255");
}

FeatureDetector::FeatureDetector(const FeatureDetectorOptions& options)
    : options_(options), detector_(nullptr) {
  options_.Check();
  detector_ = CreateDetector(options_);
}

std::vector<cv::Point2f> FeatureDetector::Detect(const cv::Mat& image, const cv::Mat& mask,
                                                 const std::vector<cv::Point2f>& existing,
                                                 const cv::Mat& road_mask) const {
  if (image.empty() || image.type() != CV_8UC1) {
    throw Error("feature detection needs a non-empty 8-bit grey image");
  }
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != image.size())) {
    throw Error("feature detection mask must be 8-bit single channel and of the image's size");
  }
  if (!road_mask.empty() && (road_mask.type() != CV_8UC1 || road_mask.size() != image.size())) {
    throw Error("feature detection road mask must be 8-bit single channel and of the image's size");
  }

  cv::Mat allowed = mask.empty() ? cv::Mat(image.size(), CV_8UC1, cv::Scalar(255)) : mask.clone();
  const int b = options_.border_px;
  if (2 * b >= image.cols || 2 * b >= image.rows) return {};
  if (b > 0) {
    allowed.rowRange(0, b).setTo(0);
    allowed.rowRange(image.rows - b, image.rows).setTo(0);
    allowed.colRange(0, b).setTo(0);
    allowed.colRange(image.cols - b, image.cols).setTo(0);
  }

  const int cell = options_.cell_size_px;
  const int grid_cols = (image.cols + cell - 1) / cell;
  const int grid_rows = (image.rows + cell - 1) / cell;
  const auto cell_index = [&](const cv::Point2f& p) {
    const int gx = std::clamp(static_cast<int>(p.x) / cell, 0, grid_cols - 1);
    const int gy = std::clamp(static_cast<int>(p.y) / cell, 0, grid_rows - 1);
    return gy * grid_cols + gx;
  };

  // A cell's cap: the road's where any of its pixels is road, as a road feature may land there.
  std::vector<int> cap(static_cast<size_t>(grid_cols) * grid_rows, options_.max_per_cell);
  if (!road_mask.empty() && options_.road_max_per_cell > options_.max_per_cell) {
    for (int gy = 0; gy < grid_rows; ++gy) {
      for (int gx = 0; gx < grid_cols; ++gx) {
        const cv::Rect cell_rect =
            cv::Rect(gx * cell, gy * cell, cell, cell) & cv::Rect(0, 0, image.cols, image.rows);
        if (cv::countNonZero(road_mask(cell_rect)) > 0) {
          cap[gy * grid_cols + gx] = options_.road_max_per_cell;
        }
      }
    }
  }
  std::vector<int> count(cap.size(), 0);
  NeighbourGrid taken(options_.min_distance_px);
  for (const cv::Point2f& p : existing) {
    if (p.x < 0 || p.y < 0 || p.x >= image.cols || p.y >= image.rows) continue;
    ++count[cell_index(p)];
    taken.Add(p);
  }
  // Skip the (costly) detection when every cell is already full.
  bool every_cell_full = true;
  for (size_t i = 0; i < count.size(); ++i) every_cell_full = every_cell_full && count[i] >= cap[i];
  if (every_cell_full) return {};

  std::vector<cv::KeyPoint> keypoints;
  const bool sift = options_.type == DetectorType::kSift;
  if (!sift || !options_.sift_half_resolution) {
    detector_->detect(image, keypoints, allowed);
  } else {
    const cv::Size half_size((image.cols + 1) / 2, (image.rows + 1) / 2);
    cv::Mat half_image;
    cv::Mat half_allowed;
    cv::resize(image, half_image, half_size, 0.0, 0.0, cv::INTER_AREA);
    cv::resize(allowed, half_allowed, half_size, 0.0, 0.0, cv::INTER_NEAREST);
    detector_->detect(half_image, keypoints, half_allowed);
  }
  for (cv::KeyPoint& kp : keypoints) {
    if (!sift) continue;
    // OpenCV's SIFT doubles its input with INTER_LINEAR (pixel centres: up = 2 x + 0.5) but
    // maps positions back with x = up / 2, so its keypoints sit 0.25 input pixels too far
    // right and down.
    kp.pt -= cv::Point2f(0.25f, 0.25f);
    // A half-resolution pixel x covers the full-resolution pixels around 2 x + 0.5.
    if (options_.sift_half_resolution) kp.pt = 2.0f * kp.pt + cv::Point2f(0.5f, 0.5f);
  }
  // Strongest first; ties broken by position so the result never depends on the detector's
  // internal (possibly parallel) output order.
  std::sort(keypoints.begin(), keypoints.end(), [](const cv::KeyPoint& a, const cv::KeyPoint& c) {
    if (a.response != c.response) return a.response > c.response;
    if (a.pt.y != c.pt.y) return a.pt.y < c.pt.y;
    return a.pt.x < c.pt.x;
  });

  std::vector<cv::Point2f> features;
  for (const cv::KeyPoint& kp : keypoints) {
    const cv::Point2f& p = kp.pt;
    if (p.x < b || p.y < b || p.x > image.cols - 1 - b || p.y > image.rows - 1 - b) continue;
    const int xi = static_cast<int>(std::lround(p.x));
    const int yi = static_cast<int>(std::lround(p.y));
    if (allowed.at<unsigned char>(yi, xi) == 0) continue;
    const int index = cell_index(p);
    const bool on_road = !road_mask.empty() && road_mask.at<unsigned char>(yi, xi) != 0;
    int& n = count[index];
    if (n >= (on_road ? cap[index] : options_.max_per_cell) || taken.HasNeighbour(p)) continue;
    ++n;
    taken.Add(p);
    features.push_back(p);
  }
  return features;
}

}  // namespace roadscale
