#include "roadscale/mapping/frame_localizer.h"

#include <gtest/gtest.h>

#include "roadscale/testing/mapping_test_scene.h"
#include "roadscale/util/error.h"
#include "roadscale/util/random.h"

namespace roadscale {
namespace {

struct LocalizationCase {
  testing::MappingTestScene scene = testing::MappingTestScene::Street(20, 1.0, 0.5);
  std::map<int64_t, Landmark> landmarks;
  std::vector<TrackObservation> observations;
  int frame = 12;

  explicit LocalizationCase(double outlier_share) {
    for (size_t id = 0; id < scene.points.size(); ++id) {
      landmarks[static_cast<int64_t>(id)].position = scene.points[id];
    }
    observations = scene.Observe(frame, 0.3, 11);
    Rng rng(5);
    for (TrackObservation& o : observations) {
      if (rng.Bernoulli(outlier_share)) o.pixel += Eigen::Vector2d(rng.Uniform(15.0, 55.0), 10.0);
    }
  }
  double CentreError(const Rigid3d& cam_from_world) const {
    return (cam_from_world.inverse().translation() -
            scene.cam_from_world[frame].inverse().translation())
        .norm();
  }
};

TEST(LocalizeFrame, RefinesAPredictedPoseDespiteOutliers) {
  const LocalizationCase c(0.2);
  const Rigid3d guess =
      MakeRigid3d(
          Eigen::AngleAxisd(1.5 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix(),
          Eigen::Vector3d(0.2, -0.1, 0.4)) *
      c.scene.cam_from_world[c.frame];
  const FrameLocalization result =
      LocalizeFrame(c.observations, c.landmarks, c.scene.camera, guess, {});
  ASSERT_TRUE(result.ok);
  EXPECT_FALSE(result.used_ransac);
  EXPECT_LT(c.CentreError(result.cam_from_world), 0.02);
  EXPECT_GT(result.num_inliers, 0.7 * result.num_landmarks);
}

TEST(LocalizeFrame, FallsBackOnRansacWhenThePredictionIsWrong) {
  const LocalizationCase c(0.3);
  // A prediction half a turn off: the refinement cannot reach the pose from there.
  const Rigid3d guess =
      MakeRigid3d(Eigen::AngleAxisd(M_PI * 0.9, Eigen::Vector3d::UnitY()).toRotationMatrix(),
                  Eigen::Vector3d(3.0, 0.0, -5.0)) *
      c.scene.cam_from_world[c.frame];
  const FrameLocalization result =
      LocalizeFrame(c.observations, c.landmarks, c.scene.camera, guess, {});
  ASSERT_TRUE(result.ok);
  EXPECT_TRUE(result.used_ransac);
  EXPECT_LT(c.CentreError(result.cam_from_world), 0.02);
}

TEST(LocalizeFrame, ALandmarkBehindThePredictionDoesNotStopTheRefinement) {
  // A wrong landmark behind the predicted camera fails the reprojection's evaluation; among
  // the refinement's residuals it would leave the pose at the prediction.
  LocalizationCase c(0.0);
  const Rigid3d truth = c.scene.cam_from_world[c.frame];
  const int64_t wrong = c.observations.front().track_id;
  c.landmarks[wrong].position = truth.inverse() * Eigen::Vector3d(0.5, 0.5, -4.0);
  const Rigid3d guess =
      MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.05, 0.0, 0.15)) * truth;
  const FrameLocalization result =
      LocalizeFrame(c.observations, c.landmarks, c.scene.camera, guess, {});
  ASSERT_TRUE(result.ok);
  EXPECT_GT(c.CentreError(guess), 0.15);
  EXPECT_LT(c.CentreError(result.cam_from_world), 0.02);
}

TEST(LocalizeFrame, TooFewLandmarksIsNoPose) {
  const LocalizationCase c(0.0);
  std::vector<TrackObservation> few(c.observations.begin(), c.observations.begin() + 8);
  const FrameLocalization result =
      LocalizeFrame(few, c.landmarks, c.scene.camera, c.scene.cam_from_world[c.frame], {});
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.num_landmarks, 8);
}

TEST(AgreesWithTwoViewDirection, TakesAStepWithinTheAngleOfTheFramePairsDirection) {
  const Eigen::Vector3d forward(0.0, 0.0, -1.0);  // cur_from_prev of a camera driving ahead
  const auto tilted = [&](double deg) {
    return MakeRigid3d(
        Eigen::Matrix3d::Identity(),
        2.5 * (Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitX()) * forward));
  };
  EXPECT_TRUE(AgreesWithTwoViewDirection(tilted(0.0), forward, 5.0));
  EXPECT_TRUE(AgreesWithTwoViewDirection(tilted(4.9), forward, 5.0));
  EXPECT_FALSE(AgreesWithTwoViewDirection(tilted(5.1), forward, 5.0));
  EXPECT_FALSE(AgreesWithTwoViewDirection(tilted(180.0), forward, 5.0));
  // The two-view direction need not be of unit length.
  EXPECT_TRUE(AgreesWithTwoViewDirection(tilted(3.0), 7.0 * forward, 5.0));
  // No translation, or no measured direction: nothing to disagree with.
  EXPECT_TRUE(AgreesWithTwoViewDirection(Rigid3d::Identity(), forward, 5.0));
  EXPECT_TRUE(AgreesWithTwoViewDirection(tilted(30.0), Eigen::Vector3d::Zero(), 5.0));
}

TEST(AngleToTwoViewDirectionDeg, MeasuresTheAngleBetweenTheStepAndThePairsDirection) {
  const Eigen::Vector3d forward(0.0, 0.0, -1.0);
  const Rigid3d sideways =
      MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1.0, 0.0, -1.0));
  EXPECT_NEAR(*AngleToTwoViewDirectionDeg(sideways, 3.0 * forward), 45.0, 1e-9);
  EXPECT_NEAR(*AngleToTwoViewDirectionDeg(sideways, -forward), 135.0, 1e-9);
  EXPECT_FALSE(AngleToTwoViewDirectionDeg(Rigid3d::Identity(), forward).has_value());
  EXPECT_FALSE(AngleToTwoViewDirectionDeg(sideways, Eigen::Vector3d::Zero()).has_value());
}

TEST(FrameLocalizerOptions, TheDirectionCheckTakesAnAngleUpToHalfATurn) {
  FrameLocalizerOptions options;
  options.max_direction_change_deg = 180.0;
  EXPECT_NO_THROW(options.Check());
  options.max_direction_change_deg = 0.0;
  EXPECT_THROW(options.Check(), Error);
  options.max_direction_change_deg = 181.0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale
