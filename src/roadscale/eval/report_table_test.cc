#include "roadscale/eval/report_table.h"

#include <gtest/gtest.h>

#include "roadscale/testing/test_trajectories.h"

namespace roadscale {
namespace {

TEST(ReportTable, SaysWhichLengthsFit) {
  // 145 m: only 100 m segments fit.
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(146);
  std::vector<Rigid3d> est = gt;
  for (Rigid3d& pose : est) pose.translation() *= 1.1;
  const std::string table = FormatEvaluationTable(EvaluateTrajectory(gt, est));
  EXPECT_NE(table.find("Frames evaluated: 146"), std::string::npos) << table;
  // 10 % too long: t_err 0.1 * 101 / 100 for each of the 5 segments of 100 m.
  EXPECT_NE(table.find("t_err 10.1000 %"), std::string::npos) << table;
  EXPECT_NE(table.find("no segment of 200 m fits a 145.0 m trajectory"), std::string::npos)
      << table;
  EXPECT_NE(table.find("no segment of 800 m fits a 145.0 m trajectory"), std::string::npos)
      << table;
  EXPECT_EQ(table.find("no segment of 100 m"), std::string::npos) << table;
  EXPECT_NE(table.find("scale 0.909091"), std::string::npos) << table;
  EXPECT_NE(table.find("est/gt 1.100000"), std::string::npos) << table;
}

TEST(ReportTable, SaysWhenNoLengthFits) {
  const std::vector<Rigid3d> gt = testing::StraightMetreSteps(46);
  const std::string table = FormatEvaluationTable(EvaluateTrajectory(gt, gt));
  EXPECT_NE(table.find("undefined: no segment of 100 m fits a 45.0 m trajectory"),
            std::string::npos)
      << table;
  EXPECT_EQ(table.find("t_err 0"), std::string::npos) << table;
}

}  // namespace
}  // namespace roadscale
