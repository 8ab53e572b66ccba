#include "roadscale/pipeline/frontend_mask_carrier.h"

#include <vector>

#include <gtest/gtest.h>

namespace roadscale {
namespace {

// A 100x80 frame's masks with a car at `car`: frame-specific, so that the test can tell
// which frame's mask the carrier hands out.
SegmentationResult ResultWithCarAt(const cv::Rect& car) {
  SegmentationResult result;
  result.labels = cv::Mat(80, 100, CV_8UC1, cv::Scalar(0));
  result.road_mask = cv::Mat(80, 100, CV_8UC1, cv::Scalar(255));
  result.dynamic_mask = cv::Mat(80, 100, CV_8UC1, cv::Scalar(0));
  result.dynamic_mask(car).setTo(255);
  cv::bitwise_not(result.dynamic_mask, result.static_mask);
  return result;
}

TEST(FrontendMaskCarrier, HandsOutASegmentedFramesOwnMaskWhenItFallsDue) {
  const cv::Rect car_in_frame0(10, 10, 20, 20), car_in_frame1(60, 40, 20, 20);
  std::vector<int> taken;
  const FrontendMaskCarrier::TakeFresh take = [&](int frame) {
    taken.push_back(frame);
    return ResultWithCarAt(frame == 0 ? car_in_frame0 : car_in_frame1);
  };
  FrontendMaskCarrier carrier(MaskCarryOptions{}, /*latency_frames=*/2,
                              Eigen::Matrix3d::Identity());
  const std::vector<Correspondence> none;

  FrontendMasks masks = carrier.Masks(0, none, take);
  EXPECT_EQ(masks.segmented_frame, -1);  // the first frame's own masks, not a late one
  carrier.AddSegmented(1);
  masks = carrier.Masks(1, none, take);
  EXPECT_EQ(masks.segmented_frame, -1);
  masks = carrier.Masks(2, none, take);
  EXPECT_EQ(masks.segmented_frame, -1);  // frame 1's result is due at frame 3
  masks = carrier.Masks(3, none, take);
  ASSERT_EQ(masks.segmented_frame, 1);
  ASSERT_FALSE(masks.segmented_dynamic_mask.empty());
  EXPECT_EQ(cv::countNonZero(masks.segmented_dynamic_mask(car_in_frame1)), 400);
  EXPECT_EQ(cv::countNonZero(masks.segmented_dynamic_mask), 400);
  masks = carrier.Masks(4, none, take);
  EXPECT_EQ(masks.segmented_frame, -1);  // handed out once
  EXPECT_EQ(taken, (std::vector<int>{0, 1}));
}

// The carried road keeps only what the camera approaches: moved 10 px down a frame, a road
// over the lower half of the frame leaves a quarter of itself below the image each frame.
// No share is lost while the road stays put, and a frame sent to the network is pending until
// its result falls due.
TEST(FrontendMaskCarrier, MeasuresTheShareOfTheRoadStillCarried) {
  const auto take = [](int) {
    SegmentationResult result = ResultWithCarAt(cv::Rect(0, 0, 10, 10));
    result.road_mask.rowRange(0, 40).setTo(0);
    return result;
  };
  const auto moved_down = [](double px) {
    std::vector<Correspondence> out;
    for (int y = 42; y < 78; y += 6) {
      for (int x = 5; x < 100; x += 10) {
        out.push_back(
            {static_cast<int64_t>(out.size()), Eigen::Vector2d(x, y), Eigen::Vector2d(x, y + px)});
      }
    }
    return out;
  };
  FrontendMaskCarrier carrier(MaskCarryOptions{}, /*latency_frames=*/2,
                              Eigen::Matrix3d::Identity());
  carrier.Masks(0, {}, take);
  EXPECT_DOUBLE_EQ(carrier.carried_road_share(), 1.0);
  carrier.Masks(1, moved_down(0.0), take);
  EXPECT_DOUBLE_EQ(carrier.carried_road_share(), 1.0);
  carrier.Masks(2, moved_down(10.0), take);
  EXPECT_NEAR(carrier.carried_road_share(), 0.75, 0.03);
  carrier.Masks(3, moved_down(10.0), take);
  EXPECT_NEAR(carrier.carried_road_share(), 0.5, 0.03);
  EXPECT_FALSE(carrier.segmentation_pending());
  carrier.AddSegmented(3);
  EXPECT_TRUE(carrier.segmentation_pending());
  carrier.Masks(4, moved_down(0.0), take);
  EXPECT_TRUE(carrier.segmentation_pending());
  carrier.Masks(5, moved_down(0.0), take);  // frame 3's result is due: its road is whole
  EXPECT_FALSE(carrier.segmentation_pending());
  EXPECT_DOUBLE_EQ(carrier.carried_road_share(), 1.0);

  // A car carried onto the road takes its pixels from the share: 400 of the road's 4,000.
  const auto take_car_on_road = [&](int frame) {
    SegmentationResult result = take(frame);
    result.dynamic_mask(cv::Rect(20, 50, 20, 20)).setTo(255);
    return result;
  };
  FrontendMaskCarrier with_car(MaskCarryOptions{}, /*latency_frames=*/2,
                               Eigen::Matrix3d::Identity());
  with_car.Masks(0, {}, take_car_on_road);
  with_car.Masks(1, moved_down(0.0), take_car_on_road);
  EXPECT_NEAR(with_car.carried_road_share(), 0.9, 1e-9);
}

}  // namespace
}  // namespace roadscale
