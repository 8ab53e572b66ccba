#include "roadscale/report/run_report.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace roadscale {
namespace {

std::vector<FrameRecord> Records(const std::vector<std::string>& statuses) {
  std::vector<FrameRecord> records;
  for (size_t i = 0; i < statuses.size(); ++i) {
    FrameRecord record;
    record.index = 100 + i;
    record.status = statuses[i];
    records.push_back(record);
  }
  return records;
}

TEST(RunReport, NoWarningWhenEveryStepIsScaled) {
  EXPECT_TRUE(ScaleWarnings(Records({"first", "ok", "ok", "stationary", "ok"})).empty());
}

TEST(RunReport, WarnsAboutAWholeUnscaledSequence) {
  const std::vector<std::string> warnings =
      ScaleWarnings(Records({"first", "unscaled", "stationary", "unscaled"}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("UNSCALED"), std::string::npos);
}

TEST(RunReport, NamesTheUnscaledStartAndLongHeldRuns) {
  std::vector<std::string> statuses = {"first", "unscaled", "unscaled", "ok"};
  for (int i = 0; i < 12; ++i) statuses.push_back("held");
  statuses.push_back("ok");
  statuses.push_back("held");  // a short run: no warning of its own
  for (int i = 0; i < 10; ++i) statuses.push_back("ok");
  const std::vector<std::string> warnings = ScaleWarnings(Records(statuses));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("frames 101-102"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("frames 104-115"), std::string::npos) << warnings[1];
}

TEST(RunReport, NamesALongBackfilledStartOnly) {
  std::vector<std::string> statuses = {"first"};
  for (int i = 0; i < 10; ++i) statuses.push_back("backfilled");
  statuses.push_back("ok");
  std::vector<std::string> warnings = ScaleWarnings(Records(statuses));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("frames 101-110: back-filled"), std::string::npos) << warnings[0];
  EXPECT_TRUE(ScaleWarnings(Records({"first", "backfilled", "backfilled", "ok"})).empty());
}

TEST(RunReport, SeriesTakeTheScaleSourcesColumnsAndTheTrueStepLength) {
  std::vector<FrameRecord> records = Records({"first", "ok", "ok"});
  records[1].scale_diagnostics_csv = "0.5,0.75,10";
  records[2].scale_diagnostics_csv = "nan,0.8,";
  std::vector<Rigid3d> gt(3, Rigid3d::Identity());
  gt[1].translation() = Eigen::Vector3d(0, 0, 1);
  gt[2].translation() = Eigen::Vector3d(0, 0, 3);
  const std::vector<Rigid3d> no_poses;
  RunReportData data(records, no_poses, gt);
  data.scale_diagnostics_header = "road_raw_scale,road_scale,road_triangulated";
  const std::vector<FrameSeries> series = RunFrameSeries(data);
  const auto find = [&](const std::string& name) -> const FrameSeries& {
    for (const FrameSeries& s : series) {
      if (s.name == name) return s;
    }
    ADD_FAILURE() << "no series " << name;
    return series.front();
  };
  EXPECT_TRUE(std::isnan(find("scale_raw").values[0]));
  EXPECT_EQ(find("scale_raw").values[1], 0.5);
  EXPECT_TRUE(std::isnan(find("scale_raw").values[2]));
  EXPECT_EQ(find("scale_filtered").values[2], 0.8);
  EXPECT_EQ(find("points_triangulated").values[1], 10);
  EXPECT_TRUE(std::isnan(find("points_triangulated").values[2]));
  EXPECT_DOUBLE_EQ(find("scale_true").values[1], 1.0);
  EXPECT_DOUBLE_EQ(find("scale_true").values[2], 2.0);
  EXPECT_EQ(find("scale_true").kind, FrameSeriesKind::kScale);
}

TEST(RunReport, KeyframeModeSeriesAreTheStepsTheMapAndTheAdjustmentPerKeyframe) {
  std::vector<FrameRecord> records = Records({"first", "ok", "ok"});
  records[1].step_length_m = 0.9;
  records[2].step_length_m = 1.1;
  records[1].scale_valid = records[2].scale_valid = true;
  records[0].scale_diagnostics_csv = "1,0,0,0";
  records[1].scale_diagnostics_csv = "0,150,0,40";
  records[2].scale_diagnostics_csv = "1,170,35.5,42";
  const std::vector<Rigid3d> no_poses;
  RunReportData data(records, no_poses, no_poses);
  data.scale_diagnostics_header = "keyframe,landmarks_seen,ba_ms,window_road_landmarks";
  const std::vector<FrameSeries> series = RunFrameSeries(data);
  const auto find = [&](const std::string& name) -> const FrameSeries* {
    for (const FrameSeries& s : series) {
      if (s.name == name) return &s;
    }
    return nullptr;
  };
  EXPECT_EQ(find("scale_raw"), nullptr);  // the per-pair scale's columns are not there
  ASSERT_NE(find("scale_filtered"), nullptr);
  EXPECT_EQ(find("scale_filtered")->values[2], 1.1);
  ASSERT_NE(find("landmarks_seen"), nullptr);
  EXPECT_EQ(find("landmarks_seen")->values[1], 150);
  ASSERT_NE(find("ms_bundle_adjustment"), nullptr);
  EXPECT_TRUE(std::isnan(find("ms_bundle_adjustment")->values[1]));  // not a keyframe
  EXPECT_EQ(find("ms_bundle_adjustment")->values[2], 35.5);
  ASSERT_NE(find("keyframe"), nullptr);
  EXPECT_EQ(find("keyframe")->values[0], 1.0);
}

}  // namespace
}  // namespace roadscale
