#include "roadscale/scale/moving_shadows.h"

#include <array>
#include <cstdint>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// Blurring first keeps the asphalt's grain and dark lane seams out of the dark regions.
constexpr int kBlurPx = 5;
// The penumbra's outer half is brighter than the threshold but still moves with the car.
constexpr int kPenumbraPx = 3;
// A shadow "touches" its object across the few pixels of the network's unsure border.
constexpr int kTouchPx = 5;

cv::Mat Disc(int radius) {
  return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1));
}

double MedianOnMask(const cv::Mat& grey, const cv::Mat& mask) {
  std::array<int64_t, 256> histogram{};
  int64_t count = 0;
  for (int y = 0; y < grey.rows; ++y) {
    const uint8_t* g = grey.ptr<uint8_t>(y);
    const uint8_t* m = mask.ptr<uint8_t>(y);
    for (int x = 0; x < grey.cols; ++x) {
      if (m[x] == 0) continue;
      ++histogram[g[x]];
      ++count;
    }
  }
  int64_t seen = 0;
  for (int level = 0; level < 256; ++level) {
    seen += histogram[level];
    if (2 * seen >= count) return level;
  }
  return 255.0;
}

// Whether dark region `region` can be the shadow of object `object`, which it touches: no
// larger than the object in the image and centred below it (within its columns). A tree's
// shadow across the road that reaches a parked car is wider than the car and mostly beside it.
bool CastBy(const cv::Mat& region_stats, int region, const cv::Mat& object_stats, int object) {
  const auto stat = [](const cv::Mat& stats, int label, int which) {
    return stats.at<int32_t>(label, which);
  };
  const int region_centre_x = stat(region_stats, region, cv::CC_STAT_LEFT) +
                              stat(region_stats, region, cv::CC_STAT_WIDTH) / 2;
  const int object_left = stat(object_stats, object, cv::CC_STAT_LEFT);
  const int object_right = object_left + stat(object_stats, object, cv::CC_STAT_WIDTH);
  return stat(region_stats, region, cv::CC_STAT_AREA) <=
             stat(object_stats, object, cv::CC_STAT_AREA) &&
         region_centre_x >= object_left && region_centre_x < object_right;
}

}  // namespace

cv::Mat MovingObjectShadows(const cv::Mat& image, const cv::Mat& road_mask,
                            const cv::Mat& dynamic_mask, double max_relative_brightness) {
  const bool image_ok = image.depth() == CV_8U && (image.channels() == 1 || image.channels() == 3);
  if (!image_ok || road_mask.type() != CV_8UC1 || dynamic_mask.type() != CV_8UC1 ||
      road_mask.size() != image.size() || dynamic_mask.size() != image.size()) {
    throw Error("MovingObjectShadows: the image and both masks must be 8-bit of one size");
  }
  cv::Mat shadows = cv::Mat::zeros(image.size(), CV_8UC1);
  if (cv::countNonZero(road_mask) == 0 || cv::countNonZero(dynamic_mask) == 0) return shadows;

  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  cv::Mat blurred;
  cv::GaussianBlur(grey, blurred, cv::Size(kBlurPx, kBlurPx), 0.0);
  const double threshold = max_relative_brightness * MedianOnMask(blurred, road_mask);
  cv::Mat dark = (blurred < threshold) & road_mask;
  cv::dilate(dark, dark, Disc(kPenumbraPx));

  cv::Mat regions, region_stats, centroids;
  const int num_regions =
      cv::connectedComponentsWithStats(dark, regions, region_stats, centroids, 8, CV_32S);
  cv::Mat objects, object_stats;
  cv::connectedComponentsWithStats(dynamic_mask, objects, object_stats, centroids, 8, CV_32S);
  // Each object's label, grown; where two objects' margins meet, the larger label's.
  cv::Mat near_objects;
  objects.convertTo(near_objects, CV_32F);
  cv::dilate(near_objects, near_objects, Disc(kTouchPx));
  std::vector<uint8_t> is_shadow(num_regions, 0);
  for (int y = 0; y < regions.rows; ++y) {
    const int32_t* r = regions.ptr<int32_t>(y);
    const float* o = near_objects.ptr<float>(y);
    for (int x = 0; x < regions.cols; ++x) {
      if (r[x] == 0 || o[x] <= 0.0f || is_shadow[r[x]] != 0) continue;
      is_shadow[r[x]] = CastBy(region_stats, r[x], object_stats, static_cast<int>(o[x])) ? 1 : 0;
    }
  }
  for (int y = 0; y < regions.rows; ++y) {
    const int32_t* r = regions.ptr<int32_t>(y);
    uint8_t* s = shadows.ptr<uint8_t>(y);
    for (int x = 0; x < regions.cols; ++x) {
      if (r[x] != 0 && is_shadow[r[x]] != 0) s[x] = 255;
    }
  }
  return shadows;
}

cv::Mat RoadWithoutMovingShadows(const cv::Mat& image, const cv::Mat& road_mask,
                                 const cv::Mat& dynamic_mask, double max_relative_brightness) {
  if (image.empty() || road_mask.empty() || dynamic_mask.empty()) return cv::Mat();
  const cv::Mat shadows =
      MovingObjectShadows(image, road_mask, dynamic_mask, max_relative_brightness);
  cv::Mat road = road_mask.clone();
  road.setTo(0, shadows);
  if (cv::countNonZero(road) == cv::countNonZero(road_mask)) return cv::Mat();
  return road;
}

ShadowFreeRoad::ShadowFreeRoad(const cv::Mat& image, const cv::Mat& road_mask,
                               const cv::Mat& dynamic_mask)
    : image_(image), road_mask_(road_mask), dynamic_mask_(dynamic_mask) {}

bool ShadowFreeRoad::HasShadows(double max_relative_brightness) {
  if (!without_shadows_) {
    without_shadows_ =
        RoadWithoutMovingShadows(image_, road_mask_, dynamic_mask_, max_relative_brightness);
  }
  return !without_shadows_->empty();
}

const cv::Mat& ShadowFreeRoad::Road(double max_relative_brightness) {
  return HasShadows(max_relative_brightness) ? *without_shadows_ : road_mask_;
}

}  // namespace roadscale
