#pragma once

#include <optional>

#include <opencv2/core.hpp>

namespace roadscale {

// The shadows that moving objects cast on the road, found where no network labels them: road
// pixels darker than `max_relative_brightness` times the road's median grey level, in
// connected dark regions that touch a moving object. Such a shadow moves with its car, not
// with the road: in dense traffic the car ahead's shadow was the strongest texture on the
// road, and a road plane aligned on it measures the car's motion (on the real KITTI traffic
// drive every keyframe pair's road alignment diverged until the shadows were taken out;
// docs/benchmark-history.md, "Shadows that move with the cars"). A car's contact shadow beneath it
// is there in any weather. A static shadow that touches a car (a parked car under a tree) is taken
// too: some road texture lost, no wrong motion kept.
//
// grey: CV_8UC1 or CV_8UC3 (BGR) image; road_mask, dynamic_mask: CV_8UC1 of the same size,
// non-zero = set (the moving objects before any dilation). Returns CV_8UC1, 255 on the
// shadows' pixels (slightly grown, so that the penumbra's edge goes with them); all zero when
// either mask is empty or all zero. Throws Error on mismatched sizes or types.
cv::Mat MovingObjectShadows(const cv::Mat& image, const cv::Mat& road_mask,
                            const cv::Mat& dynamic_mask, double max_relative_brightness);

// `road_mask` less MovingObjectShadows, or an empty Mat where that takes no road pixel (or a
// mask or the image is empty): the road alignment's second try, only where it differs.
cv::Mat RoadWithoutMovingShadows(const cv::Mat& image, const cv::Mat& road_mask,
                                 const cv::Mat& dynamic_mask, double max_relative_brightness);

// A frame's road mask less its moving objects' shadows, worked out on first use and kept:
// the road alignment's second try may need the same frame with the frame before it and again
// with the one after.
class ShadowFreeRoad {
 public:
  ShadowFreeRoad() = default;
  // Keeps the Mats' headers (the pixels are shared, not copied): they must not change after.
  ShadowFreeRoad(const cv::Mat& image, const cv::Mat& road_mask, const cv::Mat& dynamic_mask);

  // Whether RoadWithoutMovingShadows at `max_relative_brightness` (the same on every call)
  // takes any road pixel.
  bool HasShadows(double max_relative_brightness);
  // The road mask less those shadows; the road mask itself where there are none.
  const cv::Mat& Road(double max_relative_brightness);

 private:
  cv::Mat image_;
  cv::Mat road_mask_;
  cv::Mat dynamic_mask_;
  std::optional<cv::Mat> without_shadows_;  // empty Mat: no shadow on the road
};

}  // namespace roadscale
