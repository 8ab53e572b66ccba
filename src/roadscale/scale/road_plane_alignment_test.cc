#include "roadscale/scale/road_plane_alignment.h"

#include <cmath>
#include <utility>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include "roadscale/scale/moving_shadows.h"
#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

// Two frames of a rendered drive with their exact road labels and true motion.
struct RenderedPair {
  cv::Mat prev_image, cur_image, prev_road, cur_road;
  Rigid3d cur_from_prev;
  synth::RoadPlane prev_plane;
  PinholeCamera camera;
};

RenderedPair RenderPair(const char* preset, int prev, int cur, double crown_slope = -1.0) {
  synth::SceneOptions options = synth::PresetSceneOptions(preset);
  options.seed = 1;
  if (crown_slope >= 0.0) options.road.crown_slope = crown_slope;
  synth::SyntheticScene scene(options, cur + 1);
  const synth::SynthFrame a = scene.Render(prev, false);
  const synth::SynthFrame b = scene.Render(cur, false);
  RenderedPair pair;
  pair.prev_image = a.images.grey;
  pair.cur_image = b.images.grey;
  pair.prev_road = LabelsInSet(a.images.labels, {0});
  pair.cur_road = LabelsInSet(b.images.labels, {0});
  pair.cur_from_prev = b.world_from_cam.inverse() * a.world_from_cam;
  pair.prev_plane = a.road_plane;
  pair.camera = options.image.camera;
  return pair;
}

double TrueHeightPerBaseline(const RenderedPair& pair) {
  return pair.prev_plane.height / pair.cur_from_prev.translation().norm();
}

RoadPlaneAlignment Align(const RenderedPair& pair, double expected_baseline_over_height,
                         const RoadPlaneAlignmentOptions& options = {}) {
  return AlignRoadPlane(pair.prev_image, pair.cur_image, pair.prev_road, pair.cur_road, pair.camera,
                        pair.cur_from_prev, Eigen::Vector3d::UnitY(), expected_baseline_over_height,
                        options);
}

// Every road pixel sampled at every level, wherever it lies.
RoadPlaneAlignmentOptions WholeRoadOptions() {
  RoadPlaneAlignmentOptions options;
  options.max_lateral_offset = 0.0;
  options.max_distance = 0.0;
  return options;
}

TEST(RoadPlaneAlignment, MeasuresTheRoadOfARenderedStreetWithoutAPrior) {
  const RenderedPair pair = RenderPair("urban", 10, 12);
  const RoadPlaneAlignment fit = Align(pair, 0.0);
  ASSERT_TRUE(fit.ok);
  EXPECT_GT(fit.samples, 1000);
  // Measured: 0.5-0.6 % median error over 60 pairs of this drive (bench/road_alignment_accuracy).
  EXPECT_NEAR(fit.plane.height / TrueHeightPerBaseline(pair), 1.0, 0.02);
  EXPECT_LT(std::acos(fit.plane.normal.dot(pair.prev_plane.normal)) * kDegPerRad, 1.0);
}

// The masks are shared with the keyframes and the mask carrying: eroding them in place once
// changed the pipeline's road masks behind its back.
TEST(RoadPlaneAlignment, LeavesItsInputsAsTheyWere) {
  const RenderedPair pair = RenderPair("urban", 10, 12);
  const cv::Mat prev_road = pair.prev_road.clone();
  const cv::Mat cur_road = pair.cur_road.clone();
  const cv::Mat prev_image = pair.prev_image.clone();
  ASSERT_TRUE(Align(pair, 0.0).ok);
  EXPECT_EQ(cv::norm(prev_road, pair.prev_road, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(cur_road, pair.cur_road, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(prev_image, pair.prev_image, cv::NORM_INF), 0.0);
}

TEST(RoadPlaneAlignment, FollowsTheStretchedRoadOfAHighwayFromAPrior) {
  // 2.5 m a frame: the nearest road grows by a third between the frames, where KLT loses it.
  const RenderedPair pair = RenderPair("highway", 20, 21);
  const double truth = TrueHeightPerBaseline(pair);
  const RoadPlaneAlignment fit = Align(pair, 1.2 / truth);
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR(fit.plane.height / truth, 1.0, 0.02);
}

// A prior five times the truth (a map whose scale is that far off): the search around it
// does not reach the road's own minimum (three times still did on this pair); searching the
// whole range once more does.
TEST(RoadPlaneAlignment, SearchesTheWholeRangeWhereAWrongPriorFindsNothing) {
  const RenderedPair pair = RenderPair("highway", 20, 21);
  const double truth = TrueHeightPerBaseline(pair);
  const double wrong_prior = 5.0 / truth;
  const RoadPlaneAlignment near_prior = Align(pair, wrong_prior);
  EXPECT_FALSE(near_prior.ok);
  const RoadPlaneAlignment fit = AlignRoadPlaneOrSearchAll(
      pair.prev_image, pair.cur_image, pair.prev_road, pair.cur_road, pair.camera,
      pair.cur_from_prev, Eigen::Vector3d::UnitY(), wrong_prior, {});
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR(fit.plane.height / truth, 1.0, 0.02);
}

// Where the search near the prior succeeds, its result stands.
TEST(RoadPlaneAlignment, KeepsTheResultNearARightPrior) {
  const RenderedPair pair = RenderPair("highway", 20, 21);
  const double prior = 1.2 / TrueHeightPerBaseline(pair);
  const RoadPlaneAlignment near_prior = Align(pair, prior);
  ASSERT_TRUE(near_prior.ok);
  const RoadPlaneAlignment fit = AlignRoadPlaneOrSearchAll(
      pair.prev_image, pair.cur_image, pair.prev_road, pair.cur_road, pair.camera,
      pair.cur_from_prev, Eigen::Vector3d::UnitY(), prior, {});
  EXPECT_EQ(fit.plane.height, near_prior.plane.height);
  EXPECT_EQ(fit.iterations, near_prior.iterations);
}

// A crowned road falls away to both edges: the plane through the whole carriageway lies below
// the road under the car; the road near the car's own path is the plane the car stands on.
TEST(RoadPlaneAlignment, MeasuresTheCrownedRoadUnderTheCarFromItsOwnLane) {
  const RenderedPair pair = RenderPair("urban", 10, 12, 0.08);
  const double truth = TrueHeightPerBaseline(pair);
  const RoadPlaneAlignment whole = Align(pair, 0.0, WholeRoadOptions());
  RoadPlaneAlignmentOptions near_options;
  near_options.max_lateral_offset = 1.0;
  const RoadPlaneAlignment near = Align(pair, 0.0, near_options);
  ASSERT_TRUE(whole.ok);
  ASSERT_TRUE(near.ok);
  // Measured: the whole road 1.5 % too high, the car's lane 0.07 %.
  EXPECT_GT(whole.plane.height / truth, 1.008);
  EXPECT_NEAR(near.plane.height / truth, 1.0, 0.005);
}

// A car keeping its distance ahead, inside what the masks call road (the region ahead
// without segmentation; a mask carried from before the car cut in): a textured block at the
// same place in both images, on the car's own lane. Each of its pixels pulls towards no motion
// at all under the Huber loss; under the biweight the ones that do not fit the road count not.
TEST(RoadPlaneAlignment, IgnoresACarAheadInTheRoadMaskWithTheBiweight) {
  RenderedPair pair = RenderPair("urban", 10, 12);
  RoadPlaneAlignmentOptions huber;
  RoadPlaneAlignmentOptions biweight;
  biweight.loss = RoadPlaneAlignmentOptions::Loss::kTukey;
  const RoadPlaneAlignment clear_huber = Align(pair, 0.0, huber);
  const RoadPlaneAlignment clear_biweight = Align(pair, 0.0, biweight);
  // A car about 15 m ahead: 1.8 m wide, from its wheels at 1.65 m below the horizon upwards.
  cv::Mat car(70, 90, CV_8UC1);
  cv::RNG rng(7);
  rng.fill(car, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(car, car, cv::Size(5, 5), 1.5);
  const cv::Rect where(static_cast<int>(pair.camera.cx) - car.cols / 2,
                       static_cast<int>(pair.camera.cy) + 10, car.cols, car.rows);
  for (cv::Mat* image : {&pair.prev_image, &pair.cur_image}) {
    *image = image->clone();
    car.copyTo((*image)(where));
  }
  const RoadPlaneAlignment with_huber = Align(pair, 0.0, huber);
  const RoadPlaneAlignment with_biweight = Align(pair, 0.0, biweight);
  ASSERT_TRUE(clear_huber.ok && clear_biweight.ok && with_huber.ok && with_biweight.ok);
  // Measured: the biweight's plane moves by 0.24 %, the Huber loss's by 2.6 %.
  EXPECT_NEAR(with_biweight.plane.height / clear_biweight.plane.height, 1.0, 0.005);
  EXPECT_GT(std::abs(with_huber.plane.height / clear_huber.plane.height - 1.0), 0.015);
  EXPECT_NEAR(with_biweight.plane.height / TrueHeightPerBaseline(pair), 1.0, 0.01);
}

TEST(RoadPlaneAlignment, MeasuresTheRoadWithoutTheShadowOfACarThatKeepsPace) {
  RenderedPair pair = RenderPair("urban", 10, 12);
  const RoadPlaneAlignment clear = Align(pair, 0.0);
  // A car 10 m ahead that keeps pace with the camera, so that it and its sharp shadow (2 m of
  // road toward the camera, at a third of the road's light, as on the real KITTI traffic
  // drive) stand still in the image while the road moves under them.
  const int centre = static_cast<int>(pair.camera.cx);
  const int wheels = static_cast<int>(pair.camera.cy + pair.camera.fy * 1.65 / 10.0);
  const int near = static_cast<int>(pair.camera.cy + pair.camera.fy * 1.65 / 8.0);
  const cv::Rect car(centre - 65, wheels - 108, 130, 108);
  const cv::Rect shadow(centre - 65, wheels, 130, near - wheels);
  cv::Mat body(car.size(), CV_8UC1);
  cv::RNG rng(7);
  rng.fill(body, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(body, body, cv::Size(5, 5), 1.5);
  cv::Mat dynamic = cv::Mat::zeros(pair.cur_image.size(), CV_8UC1);
  dynamic(car).setTo(255);
  for (cv::Mat* image : {&pair.prev_image, &pair.cur_image}) {
    *image = image->clone();
    body.copyTo((*image)(car));
    (*image)(shadow).convertTo((*image)(shadow), -1, 0.35);
  }
  for (cv::Mat* road : {&pair.prev_road, &pair.cur_road}) {
    *road = road->clone();
    (*road)(car).setTo(0);
  }
  const RoadPlaneAlignment with_shadow = Align(pair, 0.0);

  RenderedPair cleared = pair;
  cleared.prev_road.setTo(0, MovingObjectShadows(pair.prev_image, pair.prev_road, dynamic, 0.6));
  cleared.cur_road.setTo(0, MovingObjectShadows(pair.cur_image, pair.cur_road, dynamic, 0.6));
  const RoadPlaneAlignment without_shadow = Align(cleared, 0.0);

  ASSERT_TRUE(clear.ok && without_shadow.ok);
  // Measured: with the shadow the alignment finds no plane (it stops at 2.1 times the true
  // height); without it, 0.1 % from the truth (the road without car or shadow: 0.4 %).
  EXPECT_TRUE(!with_shadow.ok ||
              std::abs(with_shadow.plane.height / TrueHeightPerBaseline(pair) - 1.0) > 0.05);
  EXPECT_NEAR(without_shadow.plane.height / TrueHeightPerBaseline(pair), 1.0, 0.01);
}

TEST(RoadPlaneAlignment, SamplesNoRoadBeyondItsLimits) {
  const RenderedPair pair = RenderPair("urban", 10, 12);
  RoadPlaneAlignmentOptions lateral = WholeRoadOptions();
  lateral.max_lateral_offset = 1.0;
  RoadPlaneAlignmentOptions ahead = WholeRoadOptions();
  ahead.max_distance = 8.0;
  // Only the road more than two camera heights to the left left in the mask ...
  RenderedPair left = pair;
  left.cur_road = pair.cur_road.clone();
  left.cur_road.setTo(0, RoadRegionAhead(pair.camera, 1e6, 2.0));
  left.cur_road.colRange(static_cast<int>(pair.camera.cx), pair.camera.width).setTo(0);
  // ... or only the road more than 10 camera heights ahead.
  RenderedPair far = pair;
  far.cur_road = pair.cur_road.clone();
  far.cur_road.setTo(0, RoadRegionAhead(pair.camera, 10.0, 1e6));
  for (const auto& [cut, limited] : {std::pair(left, lateral), std::pair(far, ahead)}) {
    ASSERT_TRUE(Align(pair, 0.0, limited).ok);
    EXPECT_GT(Align(cut, 0.0, WholeRoadOptions()).samples, 0);
    EXPECT_FALSE(Align(cut, 0.0, limited).ok);
  }
}

// The car drives on the road, so the road's normal is perpendicular to the travel; only its
// roll about the direction of travel is left to the road's pixels.
TEST(RoadPlaneAlignment, KeepsTheNormalPerpendicularToTheTravelWhenAsked) {
  const RenderedPair pair = RenderPair("urban", 10, 12);
  RoadPlaneAlignmentOptions options;
  options.tangent_to_travel = true;
  const RoadPlaneAlignment fit = Align(pair, 0.0, options);
  ASSERT_TRUE(fit.ok);
  const Eigen::Vector3d travel_in_prev =
      -(pair.cur_from_prev.linear().transpose() * pair.cur_from_prev.translation()).normalized();
  EXPECT_NEAR(fit.plane.normal.dot(travel_in_prev), 0.0, 1e-9);
  EXPECT_NEAR(fit.plane.height / TrueHeightPerBaseline(pair), 1.0, 0.01);
}

// A free normal is seen only through the road 6-33 m ahead and extrapolated to the camera:
// each pair's error in pitch becomes an error in height. Held perpendicular to the travel,
// the height is measured where the car is.
TEST(RoadPlaneAlignment, MeasuresTheHeightCloserWithTheNormalTangentToTheTravel) {
  RoadPlaneAlignmentOptions tangent;
  tangent.tangent_to_travel = true;
  double free_error = 0.0, tangent_error = 0.0;
  int pairs = 0;
  for (int prev = 40; prev < 60; prev += 2) {
    const RenderedPair pair = RenderPair("urban", prev, prev + 1);
    const double truth = TrueHeightPerBaseline(pair);
    const RoadPlaneAlignment free_fit = Align(pair, 0.0);
    const RoadPlaneAlignment tangent_fit = Align(pair, 0.0, tangent);
    ASSERT_TRUE(free_fit.ok && tangent_fit.ok) << prev;
    free_error += std::abs(free_fit.plane.height / truth - 1.0);
    tangent_error += std::abs(tangent_fit.plane.height / truth - 1.0);
    ++pairs;
  }
  // Measured: mean |error| 0.69 % free, 0.21 % tangent.
  EXPECT_LT(tangent_error, 0.5 * free_error);
  EXPECT_LT(tangent_error / pairs, 0.004);
}

// The motion's direction turned 3 degrees in pitch: the free plane that fits the road's pixels
// now tilts against the travel by about as much, which a 2 degree limit refuses.
TEST(RoadPlaneAlignment, RefusesAPlaneTiltedAgainstTheTravelBeyondTheLimit) {
  RenderedPair pair = RenderPair("urban", 10, 12);
  RoadPlaneAlignmentOptions limited;
  limited.max_pitch_to_travel_deg = 2.0;
  const RoadPlaneAlignment level = Align(pair, 0.0, limited);
  ASSERT_TRUE(level.ok);
  EXPECT_LT(level.pitch_to_travel_deg, 1.0);
  const Eigen::AngleAxisd pitch(3.0 / kDegPerRad, Eigen::Vector3d::UnitX());
  pair.cur_from_prev =
      MakeRigid3d(pair.cur_from_prev.linear(), pitch * pair.cur_from_prev.translation());
  const RoadPlaneAlignment unlimited = Align(pair, 0.0);
  ASSERT_TRUE(unlimited.ok);
  EXPECT_GT(unlimited.pitch_to_travel_deg, 2.0);
  EXPECT_FALSE(Align(pair, 0.0, limited).ok);
}

TEST(RoadPlaneAlignment, FindsNoPlaneWithoutRoadTexture) {
  RenderedPair pair = RenderPair("urban", 10, 12);
  pair.prev_image.setTo(128);
  pair.cur_image.setTo(128);
  EXPECT_FALSE(Align(pair, 0.0).ok);
}

TEST(RoadPlaneAlignment, FindsNoPlaneWithoutMotionOrRoad) {
  RenderedPair pair = RenderPair("urban", 10, 12);
  RenderedPair still = pair;
  still.cur_from_prev.translation().setZero();
  EXPECT_FALSE(Align(still, 0.0).ok);
  pair.cur_road.setTo(0);
  EXPECT_FALSE(Align(pair, 0.0).ok);
}

TEST(RoadPlaneAlignment, RejectsImagesOfTheWrongSizeOrType) {
  const RenderedPair pair = RenderPair("urban", 10, 11);
  const cv::Mat small(10, 10, CV_8UC1, cv::Scalar(0));
  cv::Mat colour;
  cv::cvtColor(pair.cur_image, colour, cv::COLOR_GRAY2BGR);
  const RoadPlaneAlignmentOptions options;
  EXPECT_THROW(AlignRoadPlane(small, pair.cur_image, pair.prev_road, pair.cur_road, pair.camera,
                              pair.cur_from_prev, Eigen::Vector3d::UnitY(), 0.0, options),
               Error);
  EXPECT_THROW(AlignRoadPlane(pair.prev_image, colour, pair.prev_road, pair.cur_road, pair.camera,
                              pair.cur_from_prev, Eigen::Vector3d::UnitY(), 0.0, options),
               Error);
  EXPECT_THROW(
      AlignRoadPlane(pair.prev_image, pair.cur_image, pair.prev_road, cv::Mat(), pair.camera,
                     pair.cur_from_prev, Eigen::Vector3d::UnitY(), 0.0, options),
      Error);
}

TEST(RoadRegionAhead, HoldsTheLevelRoadWithinTheDistanceAndWidth) {
  const PinholeCamera camera = KittiOdometryCamera();
  const cv::Mat region = RoadRegionAhead(camera, 40.0, 2.5);
  ASSERT_EQ(region.type(), CV_8UC1);
  ASSERT_EQ(region.size(), cv::Size(camera.width, camera.height));
  const int centre = static_cast<int>(camera.cx);
  // 40 heights ahead the road is fy / 40 = 18.0 px below the principal point.
  const double nearest_row = camera.cy + camera.fy / 40.0;
  EXPECT_EQ(region.at<uint8_t>(static_cast<int>(std::ceil(nearest_row)), centre), 255);
  EXPECT_EQ(region.at<uint8_t>(static_cast<int>(std::floor(nearest_row)) - 1, centre), 0);
  EXPECT_EQ(region.at<uint8_t>(static_cast<int>(camera.cy) - 20, centre), 0);  // sky
  EXPECT_EQ(region.at<uint8_t>(camera.height - 1, centre), 255);
  // The bottom corners look 3.2 heights to the side of a point 3.8 heights ahead: outside.
  EXPECT_EQ(region.at<uint8_t>(camera.height - 1, 0), 0);
  EXPECT_EQ(region.at<uint8_t>(camera.height - 1, camera.width - 1), 0);
  EXPECT_THROW(RoadRegionAhead(camera, 0.0, 2.5), Error);
  EXPECT_THROW(RoadRegionAhead(camera, 40.0, -1.0), Error);
}

TEST(RoadPlaneAlignmentOptions, RejectsInvalidValues) {
  RoadPlaneAlignmentOptions options;
  options.min_baseline_over_height = 2.0;
  options.max_baseline_over_height = 1.0;
  EXPECT_THROW(options.Check(), Error);
  options = RoadPlaneAlignmentOptions();
  options.expected_search_factor = 1.0;
  EXPECT_THROW(options.Check(), Error);
  options = RoadPlaneAlignmentOptions();
  options.max_lateral_offset = -1.0;
  EXPECT_THROW(options.Check(), Error);
  options = RoadPlaneAlignmentOptions();
  options.max_distance = std::nan("");
  EXPECT_THROW(options.Check(), Error);
  options = RoadPlaneAlignmentOptions();
  options.min_samples = options.max_samples + 1;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_NO_THROW(RoadPlaneAlignmentOptions().Check());
}

}  // namespace
}  // namespace roadscale
