#include "roadscale/eval/html_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "roadscale/eval/metrics_json.h"
#include "roadscale/eval/plots.h"
#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/string_printf.h"

namespace roadscale {
namespace {

std::string Escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Renames every id of a figure to PREFIX + its order of definition, and every reference
// (href="#id", url(#id)) with it. Cairo names its glyphs and clips alike in every document
// (one page holds several), and numbers its surfaces by a process-wide counter (the same
// figure would differ between two reports).
std::string RenameIds(const std::string& body, const std::string& prefix) {
  std::map<std::string, std::string> names;
  const std::string definition = "id=\"";
  for (size_t at = body.find(definition); at != std::string::npos;
       at = body.find(definition, at + 1)) {
    const size_t begin = at + definition.size();
    const std::string id = body.substr(begin, body.find('"', begin) - begin);
    names.emplace(id, prefix + std::to_string(names.size()));
  }
  std::string out;
  out.reserve(body.size());
  size_t copied = 0;
  // Each pattern is followed by an id ending at the given character.
  const std::vector<std::pair<std::string, char>> patterns = {
      {definition, '"'}, {"href=\"#", '"'}, {"url(#", ')'}};
  while (true) {
    size_t next = std::string::npos;
    const std::pair<std::string, char>* found = nullptr;
    for (const auto& pattern : patterns) {
      const size_t at = body.find(pattern.first, copied);
      if (at < next) {
        next = at;
        found = &pattern;
      }
    }
    if (found == nullptr) break;
    const size_t begin = next + found->first.size();
    const size_t end = body.find(found->second, begin);
    if (end == std::string::npos) break;
    const auto name = names.find(body.substr(begin, end - begin));
    out.append(body, copied, begin - copied);
    out += name != names.end() ? name->second : prefix + body.substr(begin, end - begin);
    copied = end;
  }
  out.append(body, copied, std::string::npos);
  return out;
}

// Removes ` NAME="..."` from `tag`.
void RemoveAttribute(std::string& tag, const std::string& name) {
  const size_t begin = tag.find(" " + name + "=\"");
  if (begin == std::string::npos) return;
  const size_t end = tag.find('"', begin + name.size() + 3);
  if (end != std::string::npos) tag.erase(begin, end + 1 - begin);
}

// Makes one of Cairo's SVG documents an element of the page. Without the XML declaration
// and the namespace declarations (the HTML parser puts <svg> and xlink:href in their
// namespaces itself), the page names no URL; the size comes from the CSS and the viewBox;
// ids are unique in the page and the same in every run.
std::string InlineSvg(const std::string& svg, const std::string& id_prefix,
                      const std::string& label) {
  const size_t begin = svg.find("<svg");
  const size_t tag_end = svg.find('>', begin);
  if (begin == std::string::npos || tag_end == std::string::npos) {
    throw Error("figure " + label + ": Cairo wrote no <svg> element");
  }
  std::string tag = svg.substr(begin, tag_end - begin);
  for (const char* name : {"xmlns", "xmlns:xlink", "width", "height"}) RemoveAttribute(tag, name);
  tag += " class=\"figure\" role=\"img\" aria-label=\"" + Escape(label) + "\"";
  std::string body = RenameIds(svg.substr(tag_end), id_prefix);
  while (!body.empty() && std::isspace(static_cast<unsigned char>(body.back()))) body.pop_back();
  return tag + body + "\n";
}

// Numbers of one series: its finite values, sorted.
struct Stats {
  size_t count = 0;
  double min = 0, mean = 0, median = 0, p90 = 0, max = 0;
};

Stats ComputeStats(const std::vector<double>& values) {
  std::vector<double> sorted;
  for (double value : values) {
    if (std::isfinite(value)) sorted.push_back(value);
  }
  Stats stats;
  stats.count = sorted.size();
  if (sorted.empty()) return stats;
  std::sort(sorted.begin(), sorted.end());
  double sum = 0.0;
  for (double value : sorted) sum += value;
  const size_t n = sorted.size();
  stats.min = sorted.front();
  stats.max = sorted.back();
  stats.mean = sum / static_cast<double>(n);
  stats.median = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  // Nearest rank: the smallest value with at least 90 % of the values at or below it.
  const size_t rank = static_cast<size_t>(std::ceil(0.9 * static_cast<double>(n)));
  stats.p90 = sorted[std::max<size_t>(rank, 1) - 1];
  return stats;
}

const char* KindName(FrameSeriesKind kind) {
  switch (kind) {
    case FrameSeriesKind::kScale:
      return "scale";
    case FrameSeriesKind::kCount:
      return "count";
    case FrameSeriesKind::kMilliseconds:
      return "ms";
    case FrameSeriesKind::kOther:
      return "other";
  }
  return "other";
}

std::vector<const FrameSeries*> SeriesOfKind(const HtmlReportInput& input, FrameSeriesKind kind) {
  std::vector<const FrameSeries*> out;
  for (const FrameSeries& series : input.series) {
    if (series.kind == kind) out.push_back(&series);
  }
  return out;
}

std::string NoSegmentFits(const KittiOdometryResult& kitti, float length_m) {
  return StringPrintf("no segment of %g m fits a %.1f m trajectory", static_cast<double>(length_m),
                      static_cast<double>(kitti.gt_path_length_m));
}

std::string ShortestNoSegmentFits(const KittiOdometryResult& kitti) {
  return NoSegmentFits(kitti, kitti.per_length.empty() ? 0.0f : kitti.per_length.front().length_m);
}

class Page {
 public:
  explicit Page(const HtmlReportInput& input) : input_(input) {}

  std::string Render() {
    Head();
    Header();
    TrajectorySection();
    ScaleSection();
    StatusSection();
    CountsSection();
    KittiSection();
    TimingSection();
    SummarySection();
    html_ +=
        "<footer>Written by roadscale. Figures drawn with Cairo; the page needs no "
        "network and no script.</footer>\n</main>\n</body>\n</html>\n";
    return std::move(html_);
  }

 private:
  size_t Frames() const { return input_.est_world_from_cam.size(); }
  bool HasGroundTruth() const { return !input_.gt_world_from_cam.empty(); }

  void Figure(const std::string& svg, const std::string& label, const char* css_class = "") {
    html_ += std::string("<figure class=\"") + css_class + "\">\n" +
             InlineSvg(svg, StringPrintf("f%d-", figures_++), label) + "</figure>\n";
  }

  void Note(const std::string& text) { html_ += "<p class=\"note\">" + Escape(text) + "</p>\n"; }

  void Head() {
    html_ += R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>)" + Escape(input_.title) +
             R"(</title>
<style>
body { margin: 0; background: #f4f5f7; color: #1d1f23;
  font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif; }
main { max-width: 1180px; margin: 0 auto; padding: 20px 24px 40px; }
h1 { font-size: 26px; margin: 4px 0 12px; }
h2 { font-size: 19px; margin: 0 0 10px; }
section, header { background: #fff; border: 1px solid #dde0e5; border-radius: 8px;
  padding: 16px 20px; margin: 0 0 18px; }
dl.inputs { display: grid; grid-template-columns: max-content 1fr; gap: 2px 16px; margin: 0 0 12px; }
dl.inputs dt { color: #5b6270; }
dl.inputs dd { margin: 0; font-family: ui-monospace, "DejaVu Sans Mono", monospace;
  font-size: 13.5px; overflow-wrap: anywhere; }
.warning { background: #fff4d6; border-left: 4px solid #e0a100; padding: 6px 10px; margin: 6px 0; }
.cards { display: grid; grid-template-columns: repeat(auto-fit, minmax(200px, 1fr)); gap: 12px; }
.card { border: 1px solid #dde0e5; border-radius: 6px; padding: 10px 14px; background: #fafbfc; }
.card .label { color: #5b6270; font-size: 13px; }
.card .value { font-size: 24px; font-weight: 600; font-variant-numeric: tabular-nums; }
.card .value.missing { font-size: 15px; font-weight: 400; color: #5b6270; }
.card .detail { color: #5b6270; font-size: 12.5px; }
.columns { display: grid; grid-template-columns: minmax(0, 1.1fr) minmax(0, 1fr); gap: 20px;
  align-items: start; }
.pair { display: grid; grid-template-columns: 1fr 1fr; gap: 12px; }
@media (max-width: 900px) { .columns, .pair { grid-template-columns: 1fr; } }
figure { margin: 0; }
svg.figure { display: block; width: 100%; height: auto; }
table { border-collapse: collapse; margin: 0 0 12px; font-variant-numeric: tabular-nums; }
th, td { padding: 3px 10px; border-bottom: 1px solid #e6e8ec; text-align: right; }
th { background: #f0f2f5; font-weight: 600; }
th:first-child, td:first-child, td.text { text-align: left; }
caption { text-align: left; font-weight: 600; padding: 4px 0; }
.note { color: #5b6270; margin: 6px 0; }
details pre { background: #f6f8fa; padding: 10px; overflow-x: auto; font-size: 12.5px; }
footer { color: #7a808c; font-size: 12.5px; text-align: center; }
</style>
</head>
<body>
<main>
)";
  }

  void Card(const std::string& label, const std::optional<std::string>& value,
            const std::string& detail, const std::string& missing) {
    html_ += "<div class=\"card\"><div class=\"label\">" + Escape(label) + "</div>";
    if (value) {
      html_ += "<div class=\"value\">" + Escape(*value) + "</div>";
    } else {
      html_ += "<div class=\"value missing\">" + Escape(missing) + "</div>";
    }
    html_ += "<div class=\"detail\">" + Escape(detail) + "</div></div>\n";
  }

  void Header() {
    html_ += "<header>\n<h1>" + Escape(input_.title) + "</h1>\n<dl class=\"inputs\">\n";
    for (const auto& [name, value] : input_.inputs) {
      html_ += "<dt>" + Escape(name) + "</dt><dd>" + Escape(value) + "</dd>\n";
    }
    html_ += StringPrintf("<dt>frames</dt><dd>%zu</dd>\n", Frames());
    html_ +=
        "<dt>ground truth</dt><dd>" +
        std::string(HasGroundTruth() ? StringPrintf("%zu poses", input_.gt_world_from_cam.size())
                                     : "none") +
        "</dd>\n</dl>\n";
    for (const std::string& warning : input_.warnings) {
      html_ += "<div class=\"warning\">" + Escape(warning) + "</div>\n";
    }
    html_ += "<div class=\"cards\">\n";
    if (!input_.evaluation) {
      const std::string why = HasGroundTruth() ? "not evaluated" : "no ground truth";
      for (const char* label : {"KITTI t_err", "KITTI r_err", "ATE (se3)", "Length ratio"}) {
        Card(label, std::nullopt, "", why);
      }
      html_ += "</div>\n</header>\n";
      return;
    }
    const TrajectoryEvaluation& evaluation = *input_.evaluation;
    const KittiOdometryResult& kitti = evaluation.kitti;
    const std::string segments =
        kitti.per_length.empty()
            ? StringPrintf("%d segments", kitti.n_segments())
            : StringPrintf("%d segments of %g-%g m", kitti.n_segments(),
                           static_cast<double>(kitti.per_length.front().length_m),
                           static_cast<double>(kitti.per_length.back().length_m));
    const std::string none_fits = ShortestNoSegmentFits(kitti);
    Card("KITTI t_err",
         kitti.t_err ? std::optional(StringPrintf("%.4f %%", KittiTErrPercent(*kitti.t_err)))
                     : std::nullopt,
         segments, none_fits);
    Card("KITTI r_err",
         kitti.r_err ? std::optional(StringPrintf("%.6f deg/m", KittiRErrDegPerMetre(*kitti.r_err)))
                     : std::nullopt,
         segments, none_fits);
    Card("ATE (se3)", StringPrintf("%.4f m", evaluation.errors.ate_se3_m),
         "position RMSE after rigid alignment", "");
    const TrajectoryErrors& errors = evaluation.errors;
    Card("Length ratio",
         errors.length_ratio ? std::optional(StringPrintf("%.6f", *errors.length_ratio))
                             : std::nullopt,
         StringPrintf("estimate %.1f m / ground truth %.1f m", errors.est_path_length_m,
                      errors.gt_path_length_m),
         "undefined: the ground truth does not move");
    html_ += "</div>\n</header>\n";
  }

  void MetricsTables(const TrajectoryEvaluation& evaluation) {
    const KittiOdometryResult& kitti = evaluation.kitti;
    html_ += StringPrintf(
        "<table>\n<caption>KITTI odometry metric (devkit definition, %zu frames)</caption>\n"
        "<tr><th>Segment length</th><th>Segments</th><th>t_err [%%]</th><th>r_err "
        "[deg/m]</th></tr>\n",
        evaluation.frames);
    const auto row = [&](const std::string& name, int segments, const std::optional<float>& t_err,
                         const std::optional<float>& r_err, const std::string& none_fits) {
      html_ += "<tr><td>" + Escape(name) + StringPrintf("</td><td>%d</td>", segments);
      if (t_err && r_err) {
        html_ += StringPrintf("<td>%.4f</td><td>%.6f</td></tr>\n", KittiTErrPercent(*t_err),
                              KittiRErrDegPerMetre(*r_err));
      } else {
        html_ += "<td colspan=\"2\" class=\"text\">" + Escape(none_fits) + "</td></tr>\n";
      }
    };
    row("all (mean)", kitti.n_segments(), kitti.t_err, kitti.r_err, ShortestNoSegmentFits(kitti));
    for (const KittiLengthResult& length : kitti.per_length) {
      row(StringPrintf("%g m", static_cast<double>(length.length_m)), length.n_segments,
          length.t_err, length.r_err, NoSegmentFits(kitti, length.length_m));
    }
    html_ += "</table>\n";

    const TrajectoryErrors& errors = evaluation.errors;
    html_ += "<table>\n<caption>Trajectory errors</caption>\n";
    const auto line = [&](const std::string& name, const std::string& value) {
      html_ += "<tr><td>" + Escape(name) + "</td><td>" + Escape(value) + "</td></tr>\n";
    };
    line("ATE, as given", StringPrintf("%.4f m", errors.ate_none_m));
    line("ATE, se3 aligned", StringPrintf("%.4f m", errors.ate_se3_m));
    line("ATE, sim3 aligned",
         errors.ate_sim3_m && errors.sim3_scale
             ? StringPrintf("%.4f m (scale %.6f)", *errors.ate_sim3_m, *errors.sim3_scale)
             : std::string("undefined: the estimate does not move"));
    line("RPE translation (RMSE)", StringPrintf("%.5f m", errors.rpe_trans_rmse_m));
    line("RPE rotation (RMSE)", StringPrintf("%.5f deg", errors.rpe_rot_rmse_deg));
    line("Path length, ground truth", StringPrintf("%.3f m", errors.gt_path_length_m));
    line("Path length, estimate", StringPrintf("%.3f m", errors.est_path_length_m));
    line("Length ratio (est / gt)", errors.length_ratio
                                        ? StringPrintf("%.6f", *errors.length_ratio)
                                        : std::string("undefined: the ground truth does not move"));
    line("Final drift", errors.final_drift_pct
                            ? StringPrintf("%.4f m (%.4f %% of the path)", errors.final_drift_m,
                                           *errors.final_drift_pct)
                            : StringPrintf("%.4f m", errors.final_drift_m));
    html_ += "</table>\n<details><summary>metrics.json</summary><pre>" +
             Escape(FormatMetricsJson(evaluation)) + "</pre></details>\n";
  }

  void TrajectorySection() {
    html_ += "<section>\n<h2>Trajectory</h2>\n<div class=\"columns\">\n<div>\n";
    Figure(RenderTopViewSvg(input_.gt_world_from_cam, input_.est_world_from_cam, 700, 700,
                            input_.keyframes),
           "trajectory top view");
    if (!HasGroundTruth()) Note("No ground truth: the estimate alone is drawn.");
    if (Frames() <= 1) Note("One pose: the top view shows only the start.");
    html_ += "</div>\n<div>\n";
    if (input_.evaluation) {
      MetricsTables(*input_.evaluation);
    } else {
      Note(HasGroundTruth() ? "The run was not evaluated against its ground truth."
                            : "No ground truth, so no metrics: the KITTI error, ATE, RPE and "
                              "length ratio need the true poses.");
    }
    html_ += "</div>\n</div>\n</section>\n";
  }

  void LinesSection(const std::string& heading, FrameSeriesKind kind, const std::string& y_title,
                    bool y_from_zero, const std::string& missing) {
    html_ += "<section>\n<h2>" + Escape(heading) + "</h2>\n";
    const std::vector<const FrameSeries*> series = SeriesOfKind(input_, kind);
    if (series.empty()) {
      Note(missing);
    } else {
      FrameLinePlot plot{heading, y_title, {}, y_from_zero};
      for (const FrameSeries* s : series) plot.lines.push_back({s->name, s->values});
      Figure(RenderFrameLinesSvg(plot, 1100, 360), heading);
    }
  }

  void ScaleSection() {
    LinesSection("Scale per frame", FrameSeriesKind::kScale, "Scale", false,
                 "The run recorded no scale.");
    if (!HasGroundTruth()) Note("No ground truth: the true scale is unknown.");
    html_ += "</section>\n";
  }

  void CountsSection() {
    LinesSection("Points per stage", FrameSeriesKind::kCount, "Points", true,
                 "The run recorded no per-stage counts.");
    html_ += "</section>\n";
  }

  void StatusSection() {
    html_ += "<section>\n<h2>Status per frame</h2>\n";
    const std::vector<std::string>& status = input_.frame_status;
    if (status.empty()) {
      Note("The run recorded no frame status.");
      html_ += "</section>\n";
      return;
    }
    Figure(RenderFrameStatusSvg(status, 1100, 150), "status per frame");
    // Each status's frames as ranges of consecutive frames, in order of first appearance.
    std::vector<std::pair<std::string, std::vector<std::pair<size_t, size_t>>>> runs;
    std::vector<size_t> counts;
    for (size_t i = 0; i < status.size(); ++i) {
      size_t k = 0;
      while (k < runs.size() && runs[k].first != status[i]) ++k;
      if (k == runs.size()) {
        runs.push_back({status[i], {}});
        counts.push_back(0);
      }
      ++counts[k];
      auto& ranges = runs[k].second;
      if (!ranges.empty() && ranges.back().second + 1 == i) {
        ranges.back().second = i;
      } else {
        ranges.emplace_back(i, i);
      }
    }
    html_ +=
        "<table>\n<tr><th>Status</th><th>Frames</th><th>Share</th><th>Where "
        "(frame ranges)</th></tr>\n";
    constexpr size_t kShownRanges = 12;
    for (size_t k = 0; k < runs.size(); ++k) {
      std::string where;
      const auto& ranges = runs[k].second;
      for (size_t r = 0; r < std::min(ranges.size(), kShownRanges); ++r) {
        if (r > 0) where += ", ";
        where += ranges[r].first == ranges[r].second
                     ? StringPrintf("%zu", ranges[r].first)
                     : StringPrintf("%zu-%zu", ranges[r].first, ranges[r].second);
      }
      if (ranges.size() > kShownRanges) {
        where += StringPrintf(", ... (%zu more ranges)", ranges.size() - kShownRanges);
      }
      html_ += "<tr><td>" + Escape(runs[k].first) +
               StringPrintf(
                   "</td><td>%zu</td><td>%.1f %%</td>", counts[k],
                   100.0 * static_cast<double>(counts[k]) / static_cast<double>(status.size())) +
               "<td class=\"text\">" + Escape(where) + "</td></tr>\n";
    }
    html_ += "</table>\n";
    if (status.size() != Frames()) {
      Note(StringPrintf("%zu statuses for %zu frames.", status.size(), Frames()));
    }
    html_ += "</section>\n";
  }

  void KittiSection() {
    html_ += "<section>\n<h2>KITTI error vs. segment length</h2>\n";
    if (!input_.evaluation) {
      Note(HasGroundTruth() ? "The run was not evaluated against its ground truth."
                            : "No ground truth, so no KITTI error.");
      html_ += "</section>\n";
      return;
    }
    const KittiOdometryResult& kitti = input_.evaluation->kitti;
    html_ += "<div class=\"pair\">\n";
    Figure(RenderKittiErrorSvg(kitti, KittiErrorKind::kTranslation, 640, 420),
           "translation error vs segment length");
    Figure(RenderKittiErrorSvg(kitti, KittiErrorKind::kRotation, 640, 420),
           "rotation error vs segment length");
    html_ += "</div>\n";
    Note(
        "Every length with at least one segment is drawn (the devkit draws lengths with 3 or "
        "more).");
    html_ += "</section>\n";
  }

  void TimingSection() {
    html_ += "<section>\n<h2>Timing</h2>\n";
    const std::vector<const FrameSeries*> stages =
        SeriesOfKind(input_, FrameSeriesKind::kMilliseconds);
    if (input_.wall_time_s && *input_.wall_time_s > 0.0) {
      html_ += StringPrintf(
          "<p>End to end: %zu frames in %.2f s, <b>%.2f fps</b> (stages overlap on threads).</p>\n",
          Frames(), *input_.wall_time_s, static_cast<double>(Frames()) / *input_.wall_time_s);
    }
    if (stages.empty()) {
      Note("The run recorded no stage times.");
      html_ += "</section>\n";
      return;
    }
    html_ +=
        "<table>\n<tr><th>Stage</th><th>Frames</th><th>Mean [ms]</th><th>Median [ms]</th>"
        "<th>p90 [ms]</th><th>Max [ms]</th><th>fps alone</th></tr>\n";
    const auto row = [&](const std::string& name, const Stats& stats) {
      html_ += "<tr><td>" + Escape(name) + StringPrintf("</td><td>%zu</td>", stats.count);
      if (stats.count == 0) {
        html_ += "<td colspan=\"5\" class=\"text\">no values</td></tr>\n";
        return;
      }
      html_ += StringPrintf("<td>%.2f</td><td>%.2f</td><td>%.2f</td><td>%.2f</td>", stats.mean,
                            stats.median, stats.p90, stats.max);
      html_ += stats.mean > 0.0 ? StringPrintf("<td>%.1f</td></tr>\n", 1000.0 / stats.mean)
                                : std::string("<td>-</td></tr>\n");
    };
    size_t longest = 0;
    for (const FrameSeries* stage : stages) {
      row(stage->name, ComputeStats(stage->values));
      longest = std::max(longest, stage->values.size());
    }
    // A frame's stages one after another: what a single thread would spend on it.
    std::vector<double> sum(longest, 0.0);
    for (size_t i = 0; i < longest; ++i) {
      bool any = false;
      for (const FrameSeries* stage : stages) {
        if (i < stage->values.size() && std::isfinite(stage->values[i])) {
          sum[i] += stage->values[i];
          any = true;
        }
      }
      if (!any) sum[i] = std::nan("");
    }
    if (stages.size() > 1) row("all stages, one after another", ComputeStats(sum));
    html_ += "</table>\n";
    Note(
        "p90: the smallest time that 90 % of the frames do not exceed. fps alone: 1000 / mean, "
        "the rate of the stage by itself.");
    FrameLinePlot plot{"Time per frame", "Time [ms]", {}, true};
    for (const FrameSeries* stage : stages) plot.lines.push_back({stage->name, stage->values});
    Figure(RenderFrameLinesSvg(plot, 1100, 320), "time per frame");
    html_ += "</section>\n";
  }

  void SummarySection() {
    html_ += "<section>\n<h2>Per-frame series</h2>\n";
    if (input_.series.empty()) {
      Note("The run recorded no per-frame series.");
      html_ += "</section>\n";
      return;
    }
    html_ +=
        "<table>\n<tr><th>Series</th><th>Kind</th><th>Frames with a value</th><th>Min</th>"
        "<th>Mean</th><th>Median</th><th>Max</th></tr>\n";
    for (const FrameSeries& series : input_.series) {
      const Stats stats = ComputeStats(series.values);
      html_ += "<tr><td>" + Escape(series.name) + "</td><td class=\"text\">" +
               KindName(series.kind) + StringPrintf("</td><td>%zu</td>", stats.count);
      html_ += stats.count == 0
                   ? std::string("<td colspan=\"4\" class=\"text\">no values</td>")
                   : StringPrintf("<td>%.6g</td><td>%.6g</td><td>%.6g</td><td>%.6g</td>", stats.min,
                                  stats.mean, stats.median, stats.max);
      html_ += "</tr>\n";
    }
    html_ += "</table>\n</section>\n";
  }

  const HtmlReportInput& input_;
  std::string html_;
  int figures_ = 0;
};

}  // namespace

std::string RenderHtmlReport(const HtmlReportInput& input) { return Page(input).Render(); }

void WriteHtmlReport(const std::string& path, const HtmlReportInput& input) {
  const std::string html = RenderHtmlReport(input);
  const std::filesystem::path target(path);
  if (target.has_parent_path()) {
    std::error_code error;
    std::filesystem::create_directories(target.parent_path(), error);
    if (error) ThrowFileError(path, "cannot create the report's folder: " + error.message());
  }
  WriteFileAtomically(path, html);
}

}  // namespace roadscale
