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
  FrontendMaskCarrier carrier(MaskCarryOptions{}, /*latency_frames=*/2);
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

}  // namespace
}  // namespace roadscale
