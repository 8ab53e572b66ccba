#include "roadscale/scale/depth_consistency_vote.h"

#include <gtest/gtest.h>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/testing/synthetic_road_scene.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using EdgeVisit = DepthConsistencyVoteOptions::EdgeVisit;

// Three corners and a point inside: triangles ABD, BCD, CAD. D is 30 m deep although it is
// lower in the image than A and B (20 m): edges AD and BD break the depth order.
const std::vector<Eigen::Vector2d> kPixels = {{0, 0}, {10, 0}, {5, 10}, {5, 4}};
const std::vector<Eigen::Vector3d> kPoints = {{0, 0, 20}, {0, 0, 20}, {0, 0, 5}, {0, 0, 30}};

TEST(DepthConsistencyVote, PerTriangleVotesCountSharedEdgesTwice) {
  DepthConsistencyVoteOptions options;
  EXPECT_EQ(options.edge_visit, EdgeVisit::kPerTriangle);
  const DepthConsistencyVote vote = VoteOnDepthConsistency(kPixels, kPoints, options);
  EXPECT_EQ(vote.num_triangles, 3);
  // A: AB +1, CA +1, AD -1 twice. C: BC +1, CA +1, CD +1 twice. D: AD, BD -1 twice, CD +1 twice.
  EXPECT_EQ(vote.votes, (std::vector<int>{0, 0, 4, -2}));
  EXPECT_EQ(vote.kept, std::vector<int>{2});
}

TEST(DepthConsistencyVote, PerEdgeVotesCountEachEdgeOnce) {
  DepthConsistencyVoteOptions options;
  options.edge_visit = EdgeVisit::kPerEdge;
  const DepthConsistencyVote vote = VoteOnDepthConsistency(kPixels, kPoints, options);
  EXPECT_EQ(vote.votes, (std::vector<int>{1, 1, 3, -1}));
  EXPECT_EQ(vote.kept, (std::vector<int>{0, 1, 2}));
  options.min_vote = 2;
  EXPECT_EQ(VoteOnDepthConsistency(kPixels, kPoints, options).kept, std::vector<int>{2});
}

TEST(DepthConsistencyVote, EqualRowsOrEqualDepthsKeepTheOrder) {
  // sigma = 0 is consistent (eq. 6 uses <=).
  const std::vector<Eigen::Vector2d> pixels = {{0, 0}, {10, 0}, {5, 10}};
  const std::vector<Eigen::Vector3d> points = {{0, 0, 20}, {0, 0, 7}, {0, 0, 7}};
  const DepthConsistencyVote vote =
      VoteOnDepthConsistency(pixels, points, DepthConsistencyVoteOptions());
  EXPECT_EQ(vote.votes, (std::vector<int>{2, 2, 2}));
}

TEST(DepthConsistencyVote, RemovesPointsThatBreakTheDepthOrderOfARoad) {
  const PinholeCamera camera = KittiOdometryCamera();
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  int road_kept = 0;
  int num_road = 0;
  int outliers_kept = 0;
  int num_outliers = 0;
  for (uint32_t seed : {3U, 4U, 5U, 6U}) {
    std::vector<Eigen::Vector3d> points = testing::PointsOnPlane(road, 400, -7, 7, 4, 30, seed);
    std::vector<Eigen::Vector2d> pixels;
    for (const auto& point : points) pixels.push_back(camera.Project(point));
    // Every tenth point gets a wrong depth on its own pixel's ray (a mismatch, a moving car):
    // twice or half as far.
    std::vector<bool> outlier(points.size(), false);
    for (size_t i = 0; i < points.size(); i += 10) {
      points[i] *= (i / 10) % 2 == 0 ? 2.0 : 0.5;
      outlier[i] = true;
    }
    const DepthConsistencyVote vote =
        VoteOnDepthConsistency(pixels, points, DepthConsistencyVoteOptions());
    for (int index : vote.kept) (outlier[index] ? outliers_kept : road_kept)++;
    num_outliers += 40;
    num_road += 360;
  }
  // A wrong depth breaks the order only with the neighbours on one side (above a point that
  // is too far, below one that is too near), about half of its edges: with beta_a = 1 about
  // half of such points go, and the road stays.
  EXPECT_GE(road_kept, 0.98 * num_road);
  EXPECT_LE(outliers_kept, 0.6 * num_outliers);
  // Without the tie rule (beta_a = 0) most of them would stay.
  int kept_with_ties = 0;
  std::vector<Eigen::Vector3d> points = testing::PointsOnPlane(road, 400, -7, 7, 4, 30, 3);
  std::vector<Eigen::Vector2d> pixels;
  for (const auto& point : points) pixels.push_back(camera.Project(point));
  for (size_t i = 0; i < points.size(); i += 10) points[i] *= (i / 10) % 2 == 0 ? 2.0 : 0.5;
  DepthConsistencyVoteOptions ties;
  ties.min_vote = 0;
  for (int index : VoteOnDepthConsistency(pixels, points, ties).kept) {
    kept_with_ties += index % 10 == 0 ? 1 : 0;
  }
  EXPECT_GT(kept_with_ties, 0.6 * 40);
}

TEST(PreselectRoadCandidates, KeepsRoadMaskPixelsBelowTheHorizon) {
  const PinholeCamera camera = KittiOdometryCamera();
  const std::vector<Eigen::Vector3d> points = {
      {0, 1.65, 10}, {0, -1.0, 20}, {5, 1.65, 10}, {-5, 1.65, 10}, {0, 0.5, 1e-3}};
  std::vector<Eigen::Vector2d> pixels;
  for (const auto& point : points) pixels.push_back(camera.Project(point));
  cv::Mat mask(camera.height, camera.width, CV_8UC1, cv::Scalar(0));
  mask.colRange(0, static_cast<int>(camera.cx)).setTo(255);  // road = the left half
  const Eigen::Vector3d down = Eigen::Vector3d::UnitY();
  // Point 1 is above the horizon; point 2 is off the mask; point 4 projects outside it.
  EXPECT_EQ(PreselectRoadCandidates(pixels, points, mask, down), (std::vector<int>{3}));
  EXPECT_EQ(PreselectRoadCandidates(pixels, points, cv::Mat(), down),
            (std::vector<int>{0, 2, 3, 4}));
  EXPECT_EQ(PreselectRoadCandidates(pixels, points, cv::Mat(), std::nullopt),
            (std::vector<int>{0, 1, 2, 3, 4}));
  // A camera pitched down 10 degrees: its horizon is above the image centre, so a point
  // slightly above the optical axis is below the horizon.
  const Eigen::Vector3d pitched(0.0, std::cos(0.17), std::sin(0.17));
  EXPECT_EQ(PreselectRoadCandidates({{600, 150}}, {{0, -0.5, 10}}, cv::Mat(), pitched),
            std::vector<int>{0});
  EXPECT_TRUE(PreselectRoadCandidates({{600, 150}}, {{0, -0.5, 10}}, cv::Mat(), down).empty());
}

TEST(PreselectRoadCandidates, RejectsMasksOfTheWrongType) {
  const cv::Mat colour(10, 10, CV_8UC3, cv::Scalar(255, 255, 255));
  EXPECT_THROW(PreselectRoadCandidates({{1, 1}}, {{0, 1, 5}}, colour, std::nullopt), Error);
  EXPECT_THROW(PreselectRoadCandidates({{1, 1}}, {}, cv::Mat(), std::nullopt), Error);
}

}  // namespace
}  // namespace roadscale
