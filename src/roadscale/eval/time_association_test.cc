#include "roadscale/eval/time_association.h"

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(TimeAssociation, PairsNearestTimestampsWithinTheMaximumDifference) {
  const std::vector<double> gt = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
  // The estimate is shorter, so each of its timestamps looks for the nearest ground truth:
  // 0.004 -> 0.0, 0.104 -> 0.1, 0.495 -> 0.5; 0.318 is 0.018 s from 0.3 and 0.6 is 0.1 s
  // from 0.5, too far for 0.01 s.
  const std::vector<double> est = {0.004, 0.104, 0.318, 0.495, 0.6};
  const TimeAssociation association = AssociateByTime(gt, est);
  EXPECT_EQ(association.gt_indices, (std::vector<size_t>{0, 1, 5}));
  EXPECT_EQ(association.est_indices, (std::vector<size_t>{0, 1, 3}));

  TimeAssociationOptions wide;
  wide.max_difference_s = 0.02;
  const TimeAssociation wider = AssociateByTime(gt, est, wide);
  EXPECT_EQ(wider.gt_indices, (std::vector<size_t>{0, 1, 3, 5}));
  EXPECT_EQ(wider.est_indices, (std::vector<size_t>{0, 1, 2, 3}));
}

TEST(TimeAssociation, IteratesTheShorterListAsEvoDoes) {
  // The estimate is denser: each ground-truth timestamp takes its nearest estimate.
  const std::vector<double> gt = {1.0, 2.0};
  const std::vector<double> est = {0.996, 0.999, 1.003, 1.998, 2.004};
  const TimeAssociation association = AssociateByTime(gt, est);
  EXPECT_EQ(association.gt_indices, (std::vector<size_t>{0, 1}));
  EXPECT_EQ(association.est_indices, (std::vector<size_t>{1, 3}));
}

TEST(TimeAssociation, TiesGoToTheEarlierTimestamp) {
  const std::vector<double> gt = {0.0, 0.5, 1.0, 2.0};
  const std::vector<double> est = {0.25, 0.75};
  TimeAssociationOptions options;
  options.max_difference_s = 0.25;
  const TimeAssociation association = AssociateByTime(gt, est, options);
  EXPECT_EQ(association.gt_indices, (std::vector<size_t>{0, 1}));
  EXPECT_EQ(association.est_indices, (std::vector<size_t>{0, 1}));
}

TEST(TimeAssociation, EmptyListsGiveNoPairs) {
  EXPECT_EQ(AssociateByTime({}, {1.0}).size(), 0u);
  EXPECT_EQ(AssociateByTime({1.0}, {}).size(), 0u);
}

TEST(TimeAssociation, RejectsUnsortedTimestampsAndBadOptions) {
  EXPECT_THROW(AssociateByTime({0.0, 0.2, 0.1}, {0.0}), Error);
  EXPECT_THROW(AssociateByTime({0.0}, {1.0, 1.0}), Error);
  TimeAssociationOptions options;
  options.max_difference_s = -1.0;
  EXPECT_THROW(AssociateByTime({0.0}, {0.0}, options), Error);
}

}  // namespace
}  // namespace roadscale
