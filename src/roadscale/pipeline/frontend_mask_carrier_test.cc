#include "roadscale/pipeline/frontend_mask_carrier.h"

#include <cmath>
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

// The road's homography from frame to frame is fitted on the motion the frontend measured into
// the frame before (MaskCarryOptions::road_on_motion): with the road in two small patches, as
// between the cars of a jam, the carried road follows the plane's true motion everywhere.
TEST(FrontendMaskCarrier, CarriesTheRoadOnTheMotionItWasGiven) {
  Eigen::Matrix3d k;
  k << 700, 0, 600, 0, 700, 180, 0, 0, 1;
  const auto take = [](int) {
    SegmentationResult result;
    result.labels = cv::Mat(360, 1200, CV_8UC1, cv::Scalar(0));
    result.road_mask = cv::Mat(360, 1200, CV_8UC1, cv::Scalar(0));
    result.road_mask.rowRange(200, 360).setTo(255);
    result.dynamic_mask = cv::Mat(360, 1200, CV_8UC1, cv::Scalar(0));
    cv::bitwise_not(result.dynamic_mask, result.static_mask);
    return result;
  };
  // 0.17 m straight ahead over a road 1.65 m below: H = K (I - s d n^T) K^-1.
  const Eigen::Matrix3d truth =
      k *
      (Eigen::Matrix3d::Identity() -
       (0.17 / 1.65) * Eigen::Vector3d::UnitZ() * Eigen::Vector3d::UnitY().transpose()) *
      k.inverse();
  std::vector<Correspondence> patches;
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(440, 290), Eigen::Vector2d(760, 305)}) {
    for (int y = 0; y < 20; y += 5) {
      for (int x = 0; x < 30; x += 8) {
        const Eigen::Vector2d prev = corner + Eigen::Vector2d(x, y);
        const auto id = static_cast<int64_t>(patches.size());
        const Eigen::Vector2d noise(0.3 * std::sin(1.7 * id), 0.3 * std::cos(2.3 * id));
        patches.push_back({id, prev, (truth * prev.homogeneous()).hnormalized() + noise});
      }
    }
  }
  TwoViewMotion motion;
  motion.status = MotionStatus::kOk;
  motion.direction = Eigen::Vector3d::UnitZ();
  FrontendMaskCarrier carrier(MaskCarryOptions{}, /*latency_frames=*/2, k);
  carrier.Masks(0, {}, take);
  carrier.AddMotion(motion);
  carrier.Masks(1, patches, take);
  ASSERT_FALSE(carrier.carry_failed());
  for (const Eigen::Vector2d& p :
       {Eigen::Vector2d(50, 355), Eigen::Vector2d(1150, 355), Eigen::Vector2d(600, 205)}) {
    const Eigen::Vector2d carried = (carrier.last_step() * p.homogeneous()).hnormalized();
    EXPECT_LT((carried - (truth * p.homogeneous()).hnormalized()).norm(), 1.0) << p.transpose();
  }
}

}  // namespace
}  // namespace roadscale
