#include "roadscale/batch/summary_table.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/batch/drive_record.h"
#include "roadscale/batch/summary_files.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

using roadscale::testing::TempDir;
using roadscale::testing::WriteTextFile;
using ::testing::HasSubstr;

// KITTI rows of a camera driving `steps` metres straight ahead, 1 m a frame.
std::string StraightPoses(int frames) {
  std::string text;
  for (int i = 0; i < frames; ++i) {
    text += "1 0 0 0 0 1 0 0 0 0 1 " + std::to_string(i) + "\n";
  }
  return text;
}

// A finished drive folder: 4 frames (ok, held, unscaled, ok), 3 m, 2 s of wall time, and a
// metrics.json when given.
void WriteDrive(const TempDir& batch, const std::string& name, const std::string& metrics) {
  const std::string dir = batch.File(name);
  WriteTextFile(dir + "/frames.csv",
                "frame,timestamp,status,tracks\n0,0,first,10\n1,0.1,held,10\n2,0.2,unscaled,"
                "10\n3,0.3,ok,10\n");
  WriteTextFile(dir + "/poses_kitti.txt", StraightPoses(4));
  if (!metrics.empty()) WriteTextFile(dir + "/metrics.json", metrics);
  DriveRecord record;
  record.name = name;
  record.wall_s = 2.0;
  record.outputs = RunOutputsIn(dir);
  WriteDriveRecord(dir, record);
}

std::string Metrics(const std::string& t_err, const std::string& r_err, const std::string& se3,
                    const std::string& sim3, const std::string& ratio) {
  return "{\"frames\": 4, \"kitti\": {\"t_err_pct\": " + t_err + ", \"r_err_deg_per_m\": " + r_err +
         ", \"n_segments\": 3, \"per_length\": []}, \"ate_m\": {\"none\": 1, \"se3\": " + se3 +
         ", \"sim3\": " + sim3 +
         ", \"sim3_scale\": 1}, \"rpe\": {\"trans_rmse_m\": 0, "
         "\"rot_rmse_deg\": 0}, \"length_ratio\": " +
         ratio + ", \"final_drift_m\": 0, \"final_drift_pct\": 0}";
}

TEST(SummaryTableTest, RowsCarryEachDrivesMetricsJsonNumbersExactly) {
  TempDir batch;
  WriteDrive(batch, "a", Metrics("1.2345678", "0.0061234567", "0.52", "0.31", "0.98765"));
  WriteDrive(batch, "b", Metrics("2.5", "0.01", "1.25", "null", "1.0123"));
  const BatchSummary summary = SummarizeDrives(batch.path().string(), {"a", "b"});
  ASSERT_EQ(summary.rows.size(), 2U);
  const DriveRow& a = summary.rows[0];
  EXPECT_EQ(a.report, "a/report.html");
  EXPECT_EQ(a.t_err_pct, 1.2345678);
  EXPECT_EQ(a.r_err_deg_per_m, 0.0061234567);
  EXPECT_EQ(a.r_err_deg_per_100m, 100.0 * 0.0061234567);
  EXPECT_EQ(a.ate_se3_m, 0.52);
  EXPECT_EQ(a.ate_sim3_m, 0.31);
  EXPECT_EQ(a.length_ratio, 0.98765);
  EXPECT_EQ(a.frames, 4.0);
  EXPECT_DOUBLE_EQ(*a.length_m, 3.0);
  EXPECT_EQ(a.held_share, 0.25);
  EXPECT_EQ(a.unscaled_share, 0.25);
  EXPECT_EQ(a.scaled_share, 0.5);
  EXPECT_EQ(a.frames_per_s, 2.0);
  EXPECT_FALSE(summary.rows[1].ate_sim3_m);

  ASSERT_TRUE(summary.mean);
  EXPECT_EQ(summary.mean_over, 2);
  EXPECT_DOUBLE_EQ(*summary.mean->t_err_pct, (1.2345678 + 2.5) / 2);
  EXPECT_DOUBLE_EQ(*summary.mean->ate_sim3_m, 0.31);  // over the drives that have it

  // The CSV's digits are metrics.json's.
  const std::string csv = FormatSummaryCsv(summary);
  EXPECT_THAT(csv, HasSubstr("name,frames,length_m,t_err_pct,r_err_deg_per_100m,"
                             "r_err_deg_per_m,ate_se3_m,ate_sim3_m,length_ratio,scaled_share,"
                             "held_share,unscaled_share,frames_per_s\n"));
  EXPECT_THAT(csv, HasSubstr("\na,4,3.0,1.2345678,"));
  EXPECT_THAT(csv, HasSubstr(",0.0061234567,0.52,0.31,0.98765,0.5,0.25,0.25,2.0\n"));
  EXPECT_THAT(csv, HasSubstr("\nb,4,3.0,2.5,1.0,0.01,1.25,,1.0123,"));
  const nlohmann::json json = nlohmann::json::parse(FormatSummaryJson(summary));
  EXPECT_EQ(json["drives"][0]["t_err_pct"].get<double>(), 1.2345678);
  EXPECT_TRUE(json["drives"][1]["ate_sim3_m"].is_null());
}

TEST(SummaryTableTest, MeanIsOverDrivesWithGroundTruthOnly) {
  TempDir batch;
  WriteDrive(batch, "gt", Metrics("1.0", "0.01", "0.5", "0.4", "1.0"));
  WriteDrive(batch, "video", "");
  const BatchSummary summary = SummarizeDrives(batch.path().string(), {"gt", "video"});
  ASSERT_EQ(summary.rows.size(), 2U);
  EXPECT_FALSE(summary.rows[1].ground_truth);
  EXPECT_FALSE(summary.rows[1].t_err_pct);
  EXPECT_EQ(summary.mean_over, 1);
  EXPECT_EQ(summary.mean->t_err_pct, 1.0);
}

TEST(SummaryTableTest, FailedAndMissingDrivesAreListedAndTheOthersKeepTheirRows) {
  TempDir batch;
  WriteDrive(batch, "good", Metrics("1.0", "0.01", "0.5", "0.4", "1.0"));
  DriveRecord failed;
  failed.name = "bad";
  failed.exit_status = 1;
  failed.error = "cfg.yaml:3: unknown key";
  std::filesystem::create_directories(batch.path() / "bad");
  WriteDriveRecord(batch.File("bad"), failed);
  const BatchSummary summary = SummarizeDrives(batch.path().string(), {"good", "bad", "never"});
  ASSERT_EQ(summary.rows.size(), 1U);
  EXPECT_EQ(summary.rows[0].t_err_pct, 1.0);
  ASSERT_EQ(summary.unfinished.size(), 2U);
  EXPECT_EQ(summary.unfinished[0].reason, "failed (exit status 1): cfg.yaml:3: unknown key");
  EXPECT_EQ(summary.unfinished[1].reason, "not run");
  const std::string markdown = FormatSummaryMarkdown(summary);
  EXPECT_THAT(markdown, HasSubstr("| [good](good/report.html) | 4 | 3.0 | 1.00 |"));
  EXPECT_THAT(markdown, HasSubstr("- bad: failed (exit status 1): cfg.yaml:3: unknown key"));
  EXPECT_THAT(FormatSummaryHtml(summary), HasSubstr("<a href=\"good/report.html\">good</a>"));
}

// A drive stopped by the batch's own Ctrl-C is listed as interrupted, not failed; a record
// written before the field existed reads as not interrupted.
TEST(SummaryTableTest, AnInterruptedDriveIsListedAsInterruptedNotFailed) {
  TempDir batch;
  DriveRecord stopped;
  stopped.name = "stopped";
  stopped.exit_status = 1;
  stopped.error = "interrupted after 12 frames";
  stopped.interrupted = true;
  std::filesystem::create_directories(batch.path() / "stopped");
  WriteDriveRecord(batch.File("stopped"), stopped);
  std::filesystem::create_directories(batch.path() / "old");
  WriteTextFile((batch.path() / "old" / kDriveRecordFile).string(),
                R"({"name": "old", "fingerprint": "f", "arguments": [], "exit_status": 1,
                    "error": "cfg.yaml:3: unknown key", "wall_s": 1.0, "outputs": []})");
  const BatchSummary summary = SummarizeDrives(batch.path().string(), {"stopped", "old"});
  ASSERT_EQ(summary.unfinished.size(), 2U);
  EXPECT_EQ(summary.unfinished[0].reason, "interrupted: the same command runs it again");
  EXPECT_EQ(summary.unfinished[1].reason, "failed (exit status 1): cfg.yaml:3: unknown key");
}

// A record's wall time of 1e-300 s printed a frames/s of hundreds of digits (issue 30).
TEST(SummaryTableTest, AWallTimeNoProcessTakesGivesNoFramesPerSecond) {
  TempDir batch;
  WriteDrive(batch, "a", "");
  DriveRecord record = *ReadDriveRecord(batch.File("a"));
  record.wall_s = 1e-300;
  WriteDriveRecord(batch.File("a"), record);
  const BatchSummary summary = SummarizeDrives(batch.path().string(), {"a"});
  ASSERT_EQ(summary.rows.size(), 1U);
  EXPECT_FALSE(summary.rows[0].frames_per_s.has_value());
  EXPECT_LT(FormatSummaryMarkdown(summary).size(), 1000U);
}

// Raw HTML, a link or a '|' in an error reason rendered in summary.md (issue 30).
TEST(SummaryTableTest, MarkdownShowsErrorReasonsAsText) {
  BatchSummary summary;
  summary.unfinished.push_back({"a", "failed: <script>x()</script> [y](javascript:z) a|b & c"});
  const std::string markdown = FormatSummaryMarkdown(summary);
  EXPECT_THAT(markdown, HasSubstr("- a: failed: \\<script\\>x()\\</script\\> "
                                  "\\[y\\](javascript:z) a\\|b \\& c\n"));
  EXPECT_EQ(markdown.find("<script>"), std::string::npos);
}

// One damaged drive stopped the whole summary (issue 30, defect 7): it is listed as unfinished
// with the damage, and the other drives keep their rows.
TEST(SummaryTableTest, ADamagedDriveIsListedWithTheDamageAndTheOthersKeepTheirRows) {
  TempDir batch;
  WriteDrive(batch, "a", "");
  WriteTextFile(batch.File("a/frames.csv"), "frame,tracks\n0,1\n");
  WriteDrive(batch, "good", Metrics("1.0", "0.01", "0.5", "0.4", "1.0"));
  WriteDrive(batch, "cut", Metrics("1.0", "0.01", "0.5", "0.4", "1.0"));
  WriteTextFile(batch.File("cut/batch_drive.json"), "{\"name\": \"cut\", \"finge");
  const BatchSummary summary = SummarizeDrives(batch.path().string(), {"a", "good", "cut"});
  ASSERT_EQ(summary.rows.size(), 1U);
  EXPECT_EQ(summary.rows[0].name, "good");
  ASSERT_EQ(summary.unfinished.size(), 2U);
  EXPECT_EQ(summary.unfinished[0].name, "a");
  EXPECT_THAT(summary.unfinished[0].reason, HasSubstr("frames.csv:1: no status column"));
  EXPECT_EQ(summary.unfinished[1].name, "cut");
  EXPECT_THAT(summary.unfinished[1].reason, HasSubstr("batch_drive.json: not a drive record"));
}

}  // namespace
}  // namespace roadscale::batch
