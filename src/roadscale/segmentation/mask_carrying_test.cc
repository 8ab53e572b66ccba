#include "roadscale/segmentation/mask_carrying.h"

#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

double Iou(const cv::Mat& a, const cv::Mat& b) {
  const double both = cv::countNonZero(a & b);
  const double either = cv::countNonZero(a | b);
  return either > 0 ? both / either : 1.0;
}

// The homography a road plane 1.65 m below a camera (fx = 700, 1200x360) induces when the
// camera moves `forward_m` ahead: X_cur = X_prev + t with t = (0, 0, -forward), and on the
// plane n^T X_prev = h, so H = K (I + t n^T / h) K^-1.
Eigen::Matrix3d RoadHomography(double forward_m) {
  Eigen::Matrix3d k;
  k << 700, 0, 600, 0, 700, 180, 0, 0, 1;
  const Eigen::Vector3d t(0.0, 0.0, -forward_m);
  const Eigen::Vector3d n(0.0, 1.0, 0.0);
  return k * (Eigen::Matrix3d::Identity() + t * n.transpose() / 1.65) * k.inverse();
}

Eigen::Vector2d Apply(const Eigen::Matrix3d& h, const Eigen::Vector2d& p) {
  return (h * p.homogeneous()).hnormalized();
}

TEST(MaskCarrying, FitsTheRoadHomographyToTheTracksOnTheRoadMask) {
  const Eigen::Matrix3d truth = RoadHomography(1.0);
  cv::Mat road(360, 1200, CV_8UC1, cv::Scalar(0));
  road.rowRange(200, 360).setTo(255);
  std::vector<Eigen::Vector2d> prev, cur;
  for (int y = 205; y < 350; y += 12) {
    for (int x = 300; x < 900; x += 25) {
      prev.emplace_back(x, y);
      cur.push_back(Apply(truth, prev.back()));
    }
  }
  // Tracks off the road mask (a facade: another motion) are not used.
  for (int i = 0; i < 60; ++i) {
    prev.emplace_back(100 + 15 * i, 50.0 + i);
    cur.push_back(prev.back() + Eigen::Vector2d(-3.0, 1.0));
  }
  const std::optional<Eigen::Matrix3d> fitted =
      FitRoadHomography(prev, cur, road, MaskCarryOptions());
  ASSERT_TRUE(fitted.has_value());
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(600, 300), Eigen::Vector2d(100, 355)}) {
    EXPECT_LT((Apply(*fitted, p) - Apply(truth, p)).norm(), 0.05);
  }
  // Too few road tracks: no fit.
  MaskCarryOptions strict;
  strict.road_min_tracks = static_cast<int>(prev.size());
  EXPECT_FALSE(FitRoadHomography(prev, cur, road, strict).has_value());
  EXPECT_FALSE(FitRoadHomography(prev, cur, cv::Mat(), MaskCarryOptions()).has_value());
}

// A jam: the road shows in two small patches between the cars and moves 0.17 m a frame while
// the camera turns a little. The plane's motion fitted from a prediction that is off (the last
// frame's rotation 0.2 degrees off, its direction 0.5 degrees off) maps the whole road, far
// from the patches, to within a pixel (0.1 px here; the free homography on the same tracks, 10
// px off at the lower corners).
TEST(MaskCarrying, FitsTheRoadOnThePlanesMotionFromTwoSmallPatches) {
  Eigen::Matrix3d k;
  k << 700, 0, 600, 0, 700, 180, 0, 0, 1;
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(0.004, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.002, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  const Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  const double step_over_height = 0.17 / 1.65;
  const Eigen::Matrix3d truth =
      k * rotation *
      (Eigen::Matrix3d::Identity() - step_over_height * direction * normal.transpose()) *
      k.inverse();
  cv::Mat road(360, 1200, CV_8UC1, cv::Scalar(0));
  road.rowRange(200, 360).setTo(255);
  std::vector<Eigen::Vector2d> prev, cur;
  int i = 0;
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(440, 290), Eigen::Vector2d(760, 305)}) {
    for (int y = 0; y < 20; y += 5) {
      for (int x = 0; x < 30; x += 8, ++i) {
        prev.push_back(corner + Eigen::Vector2d(x, y));
        // KLT's few tenths of a pixel, the same every run.
        const Eigen::Vector2d noise(0.3 * std::sin(1.7 * i), 0.3 * std::cos(2.3 * i));
        cur.push_back(Apply(truth, prev.back()) + noise);
      }
    }
  }
  const Eigen::Matrix3d predicted_rotation =
      Eigen::AngleAxisd(0.0035, Eigen::Vector3d::UnitX()).toRotationMatrix() * rotation;
  const Eigen::Vector3d predicted_direction =
      Eigen::AngleAxisd(0.0087, Eigen::Vector3d::UnitY()) * direction;
  const Eigen::Vector3d predicted_normal =
      (normal - normal.dot(predicted_direction) * predicted_direction).normalized();
  const std::optional<Eigen::Matrix3d> fitted =
      FitRoadHomographyOnMotion(prev, cur, road, k, predicted_rotation, predicted_direction,
                                predicted_normal, MaskCarryOptions());
  ASSERT_TRUE(fitted.has_value());
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(50, 355), Eigen::Vector2d(1150, 355),
                                   Eigen::Vector2d(600, 205), Eigen::Vector2d(600, 355)}) {
    EXPECT_LT((Apply(*fitted, p) - Apply(truth, p)).norm(), 1.0) << p.transpose();
  }
  // The same tracks off the road mask: no fit.
  EXPECT_FALSE(FitRoadHomographyOnMotion(prev, cur, cv::Mat(360, 1200, CV_8UC1, cv::Scalar(0)), k,
                                         predicted_rotation, predicted_direction, predicted_normal,
                                         MaskCarryOptions())
                   .has_value());
}

TEST(MaskCarrying, CarriesARoadMaskThroughItsHomography) {
  // A road patch (4 m wide, 8 to 14 m ahead) drawn as the image of a road rectangle; after
  // 1.5 m of travel it must be the image of the same rectangle from the new position.
  const auto draw = [](double forward_m) {
    cv::Mat mask(360, 1200, CV_8UC1, cv::Scalar(0));
    std::vector<cv::Point> corners;
    for (const auto& [x, z] : {std::pair{-2.0, 8.0}, {2.0, 8.0}, {2.0, 14.0}, {-2.0, 14.0}}) {
      const double depth = z - forward_m;
      corners.emplace_back(static_cast<int>(std::lround(600 + 700 * x / depth)),
                           static_cast<int>(std::lround(180 + 700 * 1.65 / depth)));
    }
    cv::fillConvexPoly(mask, corners, cv::Scalar(255));
    return mask;
  };
  const cv::Mat carried = CarryRoadMask(draw(0.0), RoadHomography(1.5));
  EXPECT_GT(Iou(carried, draw(1.5)), 0.97);
  EXPECT_LT(Iou(draw(0.0), draw(1.5)), 0.8);  // not carrying at all is much worse
}

// The mask of a car 1.6 m wide and 1.5 m high standing on the road `depth` metres ahead, its
// left side 1 m right of the camera, moved `own_shift_px` to the right by its own motion.
cv::Mat DrawCar(double depth, double own_shift_px) {
  cv::Mat mask(360, 1200, CV_8UC1, cv::Scalar(0));
  const double left = 600 + 700 * 1.0 / depth + own_shift_px;
  const double width = 700 * 1.6 / depth;
  const double bottom = 180 + 700 * 1.65 / depth;
  const double height = 700 * 1.5 / depth;
  cv::rectangle(mask, cv::Point2d(left, bottom - height), cv::Point2d(left + width, bottom),
                cv::Scalar(255), cv::FILLED);
  return mask;
}

double ShareMissed(const cv::Mat& carried, const cv::Mat& truth) {
  return 1.0 - cv::countNonZero(carried & truth) / double(cv::countNonZero(truth));
}

TEST(MaskCarrying, MovesACarWithTheRoadUnderItAndGrowsItForItsOwnMotion) {
  // A parked car 10 m ahead: after the camera moved 1 m it is 9 m ahead. The carried mask must
  // cover the new image of the car (here without the place it had, which is kept by default).
  const auto draw = DrawCar;
  MaskCarryOptions exact;
  exact.dynamic_growth_px_per_frame = 0.0;
  exact.dynamic_in_place = false;
  const cv::Mat carried = CarryDynamicMask(draw(10.0, 0.0), RoadHomography(1.0), 1, exact);
  EXPECT_GT(Iou(carried, draw(9.0, 0.0)), 0.93);

  // The car drives off to the side by 1.5 px a frame, which the road does not explain: two
  // frames later the 2 px a frame of growth still covers it.
  const cv::Mat moving = draw(8.0, 3.0);
  MaskCarryOptions growing;
  growing.dynamic_growth_px_per_frame = 2.0;
  growing.dynamic_in_place = false;
  const cv::Mat grown = CarryDynamicMask(draw(10.0, 0.0), RoadHomography(2.0), 2, growing);
  EXPECT_LT(ShareMissed(grown, moving), 0.02);
  // Without growth a car that drove 6 px off its road-carried place is partly missed.
  const cv::Mat faster = draw(8.0, 6.0);
  const cv::Mat ungrown = CarryDynamicMask(draw(10.0, 0.0), RoadHomography(2.0), 2, exact);
  EXPECT_GT(ShareMissed(ungrown, faster), 0.02);
  EXPECT_TRUE(CarryDynamicMask(cv::Mat(), RoadHomography(1.0), 1, exact).empty());
}

TEST(MaskCarrying, KeepsACarWhereItWasForTrafficThatKeepsPace) {
  // In a jam the car 6 m ahead moves as the camera does: after 2 m of road it is still 6 m
  // ahead, at the same pixels, while a parked car beside it comes 2 m closer. The default
  // carried mask covers both; moved with the road alone it misses a third of the first.
  const Eigen::Matrix3d road = RoadHomography(2.0);
  const cv::Mat segmented = DrawCar(6.0, 0.0) | DrawCar(12.0, -400.0);
  const cv::Mat keeping_pace = DrawCar(6.0, 0.0);
  const cv::Mat parked = DrawCar(10.0, -400.0 * 12.0 / 10.0);
  MaskCarryOptions both;
  both.dynamic_growth_px_per_frame = 0.0;
  const cv::Mat carried = CarryDynamicMask(segmented, road, 2, both);
  EXPECT_LT(ShareMissed(carried, keeping_pace), 0.01);
  EXPECT_LT(ShareMissed(carried, parked), 0.05);
  MaskCarryOptions with_road_only = both;
  with_road_only.dynamic_in_place = false;
  EXPECT_GT(ShareMissed(CarryDynamicMask(segmented, road, 2, with_road_only), keeping_pace), 0.2);
}

TEST(MaskCarrying, OptionsAreChecked) {
  MaskCarryOptions options;
  EXPECT_NO_THROW(options.Check());
  options.road_min_tracks = 3;
  EXPECT_THROW(options.Check(), Error);
  options = MaskCarryOptions();
  options.dynamic_growth_px_per_frame = -1.0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale
