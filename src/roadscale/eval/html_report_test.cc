#include "roadscale/eval/html_report.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/testing/test_trajectories.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

const double kNaN = std::nan("");

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A run of `frames` frames with ground truth, its evaluation, series and statuses.
HtmlReportInput RunWithGroundTruth(int frames) {
  HtmlReportInput input;
  input.title = "roadscale run: test drive";
  input.inputs = {{"sequence", "/data/test_drive"}, {"h0", "1.65 m"}};
  input.gt_world_from_cam = testing::CurvyDrive(frames, 1.0);
  input.est_world_from_cam =
      testing::PerturbedEstimate(input.gt_world_from_cam, 5, 0.03, 0.02, 1e-4);
  input.evaluation = EvaluateTrajectory(input.gt_world_from_cam, input.est_world_from_cam);
  FrameSeries raw{"scale_raw", FrameSeriesKind::kScale, {}};
  FrameSeries points{"points_vote", FrameSeriesKind::kCount, {}};
  FrameSeries ms{"ms_scale", FrameSeriesKind::kMilliseconds, {}};
  for (int i = 0; i < frames; ++i) {
    raw.values.push_back(i % 7 == 3 ? kNaN : 1.0 + 0.01 * std::sin(i));
    points.values.push_back(40 + i % 11);
    ms.values.push_back(2.0 + i % 3);
    input.frame_status.push_back(i % 7 == 3 ? "held" : "ok");
  }
  input.series = {raw, points, ms};
  return input;
}

TEST(HtmlReport, IsOneSelfContainedPage) {
  const std::string html = RenderHtmlReport(RunWithGroundTruth(300));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(html.substr(html.size() - 8), "</html>\n");
  for (const char* external : {"http://", "https://", "src=", "<script", "<link", "@import", "<img",
                               "<iframe", "<object"}) {
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  }
  // References inside the inline figures point into the page only.
  EXPECT_EQ(Count(html, "url("), Count(html, "url(#"));
  EXPECT_EQ(Count(html, "href=\""), Count(html, "href=\"#"));
  // Top view, scale, status, counts, t_err, r_err, time.
  EXPECT_EQ(Count(html, "<svg"), 7u);
  EXPECT_EQ(Count(html, "</svg>"), 7u);
}

TEST(HtmlReport, FigureIdsAreUniqueAndEveryReferenceResolves) {
  // Cairo names the glyphs of every document glyph0-1, ...: inlined as they are, the
  // figures would draw each other's letters.
  const std::string html = RenderHtmlReport(RunWithGroundTruth(120));
  std::set<std::string> ids;
  const std::regex id_pattern("\\sid=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), id_pattern);
       it != std::sregex_iterator(); ++it) {
    EXPECT_TRUE(ids.insert((*it)[1]).second) << "duplicate id " << (*it)[1];
  }
  ASSERT_GT(ids.size(), 20u);
  const std::regex reference_pattern("(?:href=\"#|url\\(#)([^\")]+)");
  size_t references = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), reference_pattern);
       it != std::sregex_iterator(); ++it, ++references) {
    EXPECT_EQ(ids.count((*it)[1]), 1u) << "dangling reference " << (*it)[1];
  }
  EXPECT_GT(references, 20u);
}

TEST(HtmlReport, ShowsTheMetricsItWasGiven) {
  HtmlReportInput input = RunWithGroundTruth(300);
  TrajectoryEvaluation& evaluation = *input.evaluation;
  evaluation.frames = 300;
  evaluation.kitti.t_err = 0.0123f;  // 1.23 %
  evaluation.kitti.r_err = 0.0001f;  // 0.00572958 deg/m
  evaluation.kitti.per_length = {{100.0f, 20, 0.011f, 0.0002f}, {200.0f, 0, {}, {}}};
  evaluation.kitti.gt_path_length_m = 150.0f;
  evaluation.errors.ate_se3_m = 0.4321;
  evaluation.errors.ate_sim3_m = 0.25;
  evaluation.errors.sim3_scale = 0.98765;
  evaluation.errors.length_ratio = 1.0042;
  evaluation.errors.rpe_trans_rmse_m = 0.01234;
  const std::string html = RenderHtmlReport(input);
  for (const char* expected :
       {"1.2300 %", "0.005730 deg/m", "0.4321 m", "1.004200", "<td>1.1000</td><td>0.011459</td>",
        "no segment of 200 m fits a 150.0 m trajectory", "0.2500 m (scale 0.987650)", "0.01234 m",
        "&quot;t_err_pct&quot;: 1.23"}) {
    EXPECT_NE(html.find(expected), std::string::npos) << expected;
  }
}

TEST(HtmlReport, SaysWhenNoSegmentFits) {
  HtmlReportInput input = RunWithGroundTruth(46);  // about 45 m
  ASSERT_FALSE(input.evaluation->kitti.t_err);
  const std::string html = RenderHtmlReport(input);
  EXPECT_NE(html.find("no segment of 100 m fits a 4"), std::string::npos);
  EXPECT_EQ(Count(html, "<svg"), 7u);  // the error plots say so too
}

TEST(HtmlReport, WorksWithoutGroundTruth) {
  HtmlReportInput input = RunWithGroundTruth(200);
  input.gt_world_from_cam.clear();
  input.evaluation.reset();
  const std::string html = RenderHtmlReport(input);
  EXPECT_NE(html.find("<dt>ground truth</dt><dd>none</dd>"), std::string::npos);
  EXPECT_NE(html.find("No ground truth: the estimate alone is drawn."), std::string::npos);
  EXPECT_NE(html.find("No ground truth, so no KITTI error."), std::string::npos);
  EXPECT_NE(html.find("No ground truth: the true scale is unknown."), std::string::npos);
  EXPECT_EQ(Count(html, ">no ground truth<"), 4u);  // the four headline cards
  EXPECT_EQ(html.find("metrics.json"), std::string::npos);
  EXPECT_EQ(Count(html, "<svg"), 5u);  // no KITTI error plots
}

TEST(HtmlReport, WorksWithOneFrameAndWithNothingButThePose) {
  HtmlReportInput one;
  one.title = "one frame";
  one.est_world_from_cam = {Rigid3d::Identity()};
  one.series = {{"scale_raw", FrameSeriesKind::kScale, {kNaN}},
                {"ms_frontend", FrameSeriesKind::kMilliseconds, {4.0}}};
  one.frame_status = {"first"};
  const std::string html = RenderHtmlReport(one);
  EXPECT_NE(html.find("One pose: the top view shows only the start."), std::string::npos);
  EXPECT_EQ(Count(html, "<svg"), 4u);  // top view, scale ("no values"), status, time
  EXPECT_NE(html.find("<td>first</td><td>1</td><td>100.0 %</td>"), std::string::npos);

  HtmlReportInput bare;
  bare.est_world_from_cam = {Rigid3d::Identity()};
  const std::string bare_html = RenderHtmlReport(bare);
  EXPECT_EQ(Count(bare_html, "<svg"), 1u);
  for (const char* note : {"The run recorded no scale.", "The run recorded no frame status.",
                           "The run recorded no stage times.", "no per-frame series"}) {
    EXPECT_NE(bare_html.find(note), std::string::npos) << note;
  }
}

TEST(HtmlReport, EscapesEveryText) {
  HtmlReportInput input = RunWithGroundTruth(50);
  input.title = "<script>alert(1)</script> & \"x\"";
  input.inputs = {{"<b>name</b>", "a<script>b"}};
  input.warnings = {"<script>warn</script>"};
  input.series.push_back({"<script>s", FrameSeriesKind::kOther, {1.0}});
  input.frame_status.back() = "<script>st";
  const std::string html = RenderHtmlReport(input);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_NE(html.find("<title>&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;x&quot;</title>"),
            std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;name&lt;/b&gt;"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;warn&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("<td>&lt;script&gt;s</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>&lt;script&gt;st</td>"), std::string::npos);
}

TEST(HtmlReport, TimingTableHasKnownStatistics) {
  HtmlReportInput input;
  input.est_world_from_cam.assign(11, Rigid3d::Identity());
  input.series = {
      {"ms_a", FrameSeriesKind::kMilliseconds, {10, 1, 9, 2, 8, 3, 7, 4, 6, 5, kNaN}},
      {"ms_b", FrameSeriesKind::kMilliseconds, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}},
  };
  input.wall_time_s = 0.5;
  const std::string html = RenderHtmlReport(input);
  // Mean 5.5, median 5.5, p90 (nearest rank 9 of 10) 9, max 10, 1000 / 5.5 fps.
  EXPECT_NE(html.find("<td>ms_a</td><td>10</td><td>5.50</td><td>5.50</td><td>9.00</td>"
                      "<td>10.00</td><td>181.8</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>ms_b</td><td>11</td><td>1.00</td><td>1.00</td><td>1.00</td>"
                      "<td>1.00</td><td>1000.0</td>"),
            std::string::npos);
  // Sums per frame: 11, 2, 10, 3, 9, 4, 8, 5, 7, 6 and 1 (frame 10 has only ms_b).
  EXPECT_NE(html.find("<td>all stages, one after another</td><td>11</td><td>6.00</td>"
                      "<td>6.00</td><td>10.00</td><td>11.00</td><td>166.7</td>"),
            std::string::npos);
  EXPECT_NE(html.find("11 frames in 0.50 s, <b>22.00 fps</b>"), std::string::npos);
}

TEST(HtmlReport, StatusSummaryCountsFramesAndRanges) {
  HtmlReportInput input;
  input.est_world_from_cam.assign(8, Rigid3d::Identity());
  input.frame_status = {"ok", "ok", "held", "held", "ok", "stationary", "held", "ok"};
  const std::string html = RenderHtmlReport(input);
  EXPECT_NE(html.find("<td>ok</td><td>4</td><td>50.0 %</td><td class=\"text\">0-1, 4, 7</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>held</td><td>3</td><td>37.5 %</td><td class=\"text\">2-3, 6</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>stationary</td><td>1</td><td>12.5 %</td><td class=\"text\">5</td>"),
            std::string::npos);
}

TEST(HtmlReport, WritesAtomicallyAndReplacesAnOldReport) {
  testing::TempDir dir;
  const std::string path = dir.File("out/nested/report.html");
  HtmlReportInput input = RunWithGroundTruth(60);
  WriteHtmlReport(path, input);
  input.title = "second version";
  WriteHtmlReport(path, input);
  const std::string html = testing::ReadFileBytes(path);
  EXPECT_EQ(html, RenderHtmlReport(input));
  EXPECT_NE(html.find("<h1>second version</h1>"), std::string::npos);
  // No temporary file is left beside it.
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.File("out/nested"))) {
    ++files;
    EXPECT_EQ(entry.path().filename(), "report.html");
  }
  EXPECT_EQ(files, 1u);
}

TEST(HtmlReport, UnwritablePathIsAnErrorNamingIt) {
  testing::TempDir dir;
  const std::string file = testing::WriteTextFile(dir.File("not_a_folder"), "x");
  HtmlReportInput input;
  input.est_world_from_cam = {Rigid3d::Identity()};
  try {
    WriteHtmlReport(file + "/report.html", input);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not_a_folder/report.html"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace roadscale
