#include "roadscale/frontend/feature_detector.h"

#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/testing/frontend_test_util.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::map<std::pair<int, int>, int> CountPerCell(const std::vector<cv::Point2f>& points, int cell) {
  std::map<std::pair<int, int>, int> count;
  for (const cv::Point2f& p : points)
    ++count[{static_cast<int>(p.x) / cell, static_cast<int>(p.y) / cell}];
  return count;
}

TEST(FeatureDetector, EveryDetectorFindsSpreadFeatures) {
  const cv::Mat image = testing::SyntheticTexture(400, 200);
  for (const DetectorType type : {DetectorType::kSift, DetectorType::kOrb, DetectorType::kBrisk,
                                  DetectorType::kAkaze, DetectorType::kFast}) {
    FeatureDetectorOptions options;
    options.type = type;
    options.cell_size_px = 50;
    options.max_per_cell = 3;
    const std::vector<cv::Point2f> features = FeatureDetector(options).Detect(image, cv::Mat());
    const auto count = CountPerCell(features, 50);
    // 8 x 4 cells of texture: nearly all get features, none more than the cap.
    EXPECT_GE(count.size(), 28u) << DetectorTypeName(type);
    for (const auto& [cell, n] : count) EXPECT_LE(n, 3) << DetectorTypeName(type);
    for (const cv::Point2f& p : features) {
      EXPECT_GE(p.x, options.border_px);
      EXPECT_GE(p.y, options.border_px);
      EXPECT_LT(p.x, image.cols - options.border_px);
      EXPECT_LT(p.y, image.rows - options.border_px);
    }
  }
}

// The road's cells take more features than the rest where a road mask is given; without one,
// every cell has the common cap.
TEST(FeatureDetector, TheRoadGetsItsOwnCapPerCell) {
  const cv::Mat image = testing::SyntheticTexture(400, 200);
  cv::Mat road(image.size(), CV_8UC1, cv::Scalar(0));
  road.rowRange(100, 200).setTo(255);
  FeatureDetectorOptions options;
  options.max_per_cell = 2;
  options.road_max_per_cell = 6;
  const FeatureDetector detector(options);
  int road_cells_above_common_cap = 0;
  for (const auto& [cell, n] : CountPerCell(detector.Detect(image, cv::Mat(), {}, road), 50)) {
    EXPECT_LE(n, cell.second >= 2 ? 6 : 2) << "cell " << cell.first << "," << cell.second;
    road_cells_above_common_cap += cell.second >= 2 && n > 2;
  }
  EXPECT_GE(road_cells_above_common_cap, 8);
  for (const auto& [cell, n] : CountPerCell(detector.Detect(image, cv::Mat()), 50)) {
    EXPECT_LE(n, 2);
  }
  EXPECT_THROW(detector.Detect(image, cv::Mat(), {}, cv::Mat(10, 10, CV_8UC1)), Error);
}

TEST(FeatureDetector, HalfResolutionSiftFindsABlobAtItsFullResolutionPosition) {
  // One dark Gaussian blob (sigma 4 px) on a flat image: SIFT's strongest response is its
  // centre, whatever resolution it runs at.
  cv::Mat image(160, 200, CV_8UC1);
  const double cx = 97.3;
  const double cy = 71.6;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const double r2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
      image.at<unsigned char>(y, x) =
          cv::saturate_cast<unsigned char>(200.0 - 150.0 * std::exp(-r2 / (2.0 * 16.0)));
    }
  }
  for (const bool half : {true, false}) {
    FeatureDetectorOptions options;
    options.sift_half_resolution = half;
    options.max_per_cell = 1;
    options.cell_size_px = 200;
    const std::vector<cv::Point2f> features = FeatureDetector(options).Detect(image, cv::Mat());
    ASSERT_EQ(features.size(), 1u) << "half " << half;
    EXPECT_NEAR(features[0].x, cx, 0.03) << "half " << half;
    EXPECT_NEAR(features[0].y, cy, 0.03) << "half " << half;
  }
}

TEST(FeatureDetector, RespectsTheMask) {
  const cv::Mat image = testing::SyntheticTexture(300, 200);
  cv::Mat mask(image.size(), CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(0, 100, 300, 100)).setTo(255);  // bottom half only
  const std::vector<cv::Point2f> features = FeatureDetector({}).Detect(image, mask);
  ASSERT_FALSE(features.empty());
  for (const cv::Point2f& p : features) EXPECT_GE(p.y, 99.5f);
}

TEST(FeatureDetector, TopsUpAroundExistingPointsWithMinimumDistance) {
  const cv::Mat image = testing::SyntheticTexture(300, 200);
  FeatureDetectorOptions options;
  options.cell_size_px = 100;
  options.max_per_cell = 5;
  options.min_distance_px = 12.0;
  const FeatureDetector detector(options);
  // Cell (0, 0) is full already; cell (1, 0) holds one point.
  std::vector<cv::Point2f> existing = {{20, 20}, {40, 40}, {60, 60}, {80, 80}, {30, 70}, {150, 50}};
  const std::vector<cv::Point2f> features = detector.Detect(image, cv::Mat(), existing);
  std::vector<cv::Point2f> all = existing;
  all.insert(all.end(), features.begin(), features.end());
  const auto count = CountPerCell(all, 100);
  EXPECT_EQ(count.at({0, 0}), 5);
  EXPECT_EQ(count.at({1, 0}), 5);
  for (size_t i = 0; i < features.size(); ++i) {
    for (size_t j = 0; j < all.size(); ++j) {
      if (existing.size() + i == j) continue;
      EXPECT_GE(cv::norm(features[i] - all[j]), 12.0);
    }
  }
}

TEST(FeatureDetector, SkipsDetectionWhenEveryCellIsFull) {
  const cv::Mat image = testing::SyntheticTexture(100, 100);
  FeatureDetectorOptions options;
  options.cell_size_px = 100;
  options.max_per_cell = 1;
  EXPECT_TRUE(FeatureDetector(options).Detect(image, cv::Mat(), {{50, 50}}).empty());
}

TEST(FeatureDetector, FlatImageHasNoFeatures) {
  const cv::Mat image(120, 160, CV_8UC1, cv::Scalar(90));
  EXPECT_TRUE(FeatureDetector({}).Detect(image, cv::Mat()).empty());
}

TEST(FeatureDetector, ParsesNamesAndRejectsBadInput) {
  EXPECT_EQ(ParseDetectorType("sift"), DetectorType::kSift);
  EXPECT_EQ(ParseDetectorType("akaze"), DetectorType::kAkaze);
  for (const char* name : {"sift", "orb", "brisk", "akaze", "fast"}) {
    EXPECT_EQ(DetectorTypeName(ParseDetectorType(name)), name);
  }
  EXPECT_THROW(ParseDetectorType("surf"), Error);
  FeatureDetectorOptions bad;
  bad.max_per_cell = 0;
  EXPECT_THROW(bad.Check(), Error);
  EXPECT_THROW(FeatureDetector{bad}, Error);
  const FeatureDetector detector({});
  EXPECT_THROW(detector.Detect(cv::Mat(50, 50, CV_8UC3), cv::Mat()), Error);
  EXPECT_THROW(detector.Detect(cv::Mat(50, 50, CV_8UC1), cv::Mat(40, 50, CV_8UC1)), Error);
}

}  // namespace
}  // namespace roadscale
