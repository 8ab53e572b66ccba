#include "roadscale/scale/moving_shadows.h"

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// A 200x120 street: grey road (140) in the bottom 60 rows with a textured grain, a car (its
// mask and dark body) standing on the road at columns 80-119, rows 40-79, its shadow (50) on
// the road below it at rows 80-99, and a static shadow (50) on the road away from any car at
// columns 10-39, rows 90-109.
struct Street {
  cv::Mat image{120, 200, CV_8UC1, cv::Scalar(200)};
  cv::Mat road{120, 200, CV_8UC1, cv::Scalar(0)};
  cv::Mat car{120, 200, CV_8UC1, cv::Scalar(0)};
  cv::Rect car_box{80, 40, 40, 40};
  cv::Rect car_shadow{80, 80, 40, 20};
  cv::Rect tree_shadow{10, 90, 30, 20};

  Street() {
    road.rowRange(60, 120).setTo(255);
    road(car_box).setTo(0);
    car(car_box).setTo(255);
    image.rowRange(60, 120).setTo(140);
    for (int y = 60; y < 120; ++y) {
      for (int x = 0; x < 200; ++x)
        image.at<uchar>(y, x) += static_cast<uchar>((x * 7 + y * 3) % 9);
    }
    image(car_box).setTo(30);
    image(car_shadow).setTo(50);
    image(tree_shadow).setTo(50);
  }
};

int CountIn(const cv::Mat& mask, const cv::Rect& box) { return cv::countNonZero(mask(box)); }

TEST(MovingObjectShadows, TakesTheDarkRoadThatTouchesACarAndLeavesAStaticShadow) {
  const Street street;
  const cv::Mat shadows = MovingObjectShadows(street.image, street.road, street.car, 0.6);
  ASSERT_EQ(shadows.type(), CV_8UC1);
  ASSERT_EQ(shadows.size(), street.image.size());
  EXPECT_EQ(CountIn(shadows, street.car_shadow), street.car_shadow.area());
  EXPECT_EQ(CountIn(shadows, street.tree_shadow), 0);
  // The lit road around them stays road, but for the penumbra's few pixels.
  const cv::Rect lit_road(130, 60, 70, 60);
  EXPECT_EQ(CountIn(shadows, lit_road), 0);
  EXPECT_LT(CountIn(shadows, cv::Rect(0, 60, 200, 60)), street.car_shadow.area() + 400);
}

TEST(MovingObjectShadows, LeavesADarkRegionThatTouchesACarButIsLargerOrBesideIt) {
  // A building's shadow across the whole road below the car: it touches the car, but it is
  // larger than the car in the image.
  Street across;
  across.image(cv::Rect(0, 80, 200, 40)).setTo(50);
  EXPECT_EQ(cv::countNonZero(MovingObjectShadows(across.image, across.road, across.car, 0.6)), 0);
  // A shadow as small as the car's, touching its side, but centred beside it.
  Street beside;
  const cv::Rect side(120, 60, 40, 20);
  beside.image(side).setTo(50);
  beside.image(beside.car_shadow).setTo(140);
  EXPECT_EQ(cv::countNonZero(MovingObjectShadows(beside.image, beside.road, beside.car, 0.6)), 0);
}

TEST(MovingObjectShadows, ALowerThresholdKeepsAShadowThatIsNotDarkEnough) {
  const Street street;
  // The shadow is 50 / ~144 = 0.35 of the road.
  EXPECT_GT(cv::countNonZero(MovingObjectShadows(street.image, street.road, street.car, 0.4)), 0);
  EXPECT_EQ(cv::countNonZero(MovingObjectShadows(street.image, street.road, street.car, 0.3)), 0);
}

TEST(MovingObjectShadows, NothingWithoutAMovingObjectOrARoad) {
  const Street street;
  const cv::Mat none = cv::Mat::zeros(street.image.size(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(MovingObjectShadows(street.image, street.road, none, 0.6)), 0);
  EXPECT_EQ(cv::countNonZero(MovingObjectShadows(street.image, none, street.car, 0.6)), 0);
}

TEST(MovingObjectShadows, TakesAColourImageAsItsGrey) {
  const Street street;
  cv::Mat colour;
  cv::cvtColor(street.image, colour, cv::COLOR_GRAY2BGR);
  const cv::Mat grey_result = MovingObjectShadows(street.image, street.road, street.car, 0.6);
  const cv::Mat colour_result = MovingObjectShadows(colour, street.road, street.car, 0.6);
  EXPECT_EQ(cv::countNonZero(grey_result != colour_result), 0);
}

TEST(RoadWithoutMovingShadows, IsTheRoadLessTheShadowsOrEmptyWhereNoneIsTaken) {
  const Street street;
  const cv::Mat road = RoadWithoutMovingShadows(street.image, street.road, street.car, 0.6);
  ASSERT_FALSE(road.empty());
  EXPECT_EQ(CountIn(road, street.car_shadow), 0);
  EXPECT_EQ(CountIn(road, street.tree_shadow), street.tree_shadow.area());
  const cv::Mat none = cv::Mat::zeros(street.image.size(), CV_8UC1);
  EXPECT_TRUE(RoadWithoutMovingShadows(street.image, street.road, none, 0.6).empty());
  EXPECT_TRUE(RoadWithoutMovingShadows(street.image, street.road, cv::Mat(), 0.6).empty());
}

TEST(ShadowFreeRoad, WorksTheRoadOutOnceAndIsTheRoadMaskWhereNoShadowIsTaken) {
  const Street street;
  ShadowFreeRoad with_car(street.image, street.road, street.car);
  ASSERT_TRUE(with_car.HasShadows(0.6));
  const cv::Mat& road = with_car.Road(0.6);
  EXPECT_EQ(cv::countNonZero(road !=
                             RoadWithoutMovingShadows(street.image, street.road, street.car, 0.6)),
            0);
  EXPECT_EQ(&with_car.Road(0.6), &road);  // the same Mat, not worked out again
  ShadowFreeRoad without_car(street.image, street.road, cv::Mat());
  EXPECT_FALSE(without_car.HasShadows(0.6));
  EXPECT_EQ(without_car.Road(0.6).data, street.road.data);
  EXPECT_FALSE(ShadowFreeRoad().HasShadows(0.6));
}

TEST(MovingObjectShadows, RefusesMasksOfAnotherSize) {
  const Street street;
  const cv::Mat small = cv::Mat::zeros(10, 10, CV_8UC1);
  EXPECT_THROW(MovingObjectShadows(street.image, small, street.car, 0.6), Error);
  EXPECT_THROW(MovingObjectShadows(street.image, street.road, small, 0.6), Error);
}

}  // namespace
}  // namespace roadscale
