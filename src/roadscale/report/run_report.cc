#include "roadscale/report/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include "roadscale/eval/metrics_json.h"
#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> SplitCsv(const std::string& text) {
  std::vector<std::string> fields;
  std::stringstream stream(text);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  if (!text.empty() && text.back() == ',') fields.emplace_back();
  return fields;
}

double ParseOrNaN(const std::string& text) {
  if (text.empty()) return kNaN;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return end == text.c_str() ? kNaN : value;
}

std::string FrameSpan(size_t first, size_t last) {
  return first == last ? "frame " + std::to_string(first)
                       : "frames " + std::to_string(first) + "-" + std::to_string(last);
}

}  // namespace

std::vector<std::string> ScaleWarnings(const std::vector<FrameRecord>& records) {
  std::vector<std::string> warnings;
  size_t unscaled = 0;
  size_t held = 0;
  size_t moving = 0;
  for (const FrameRecord& record : records) {
    if (record.status == "unscaled") ++unscaled;
    if (record.status == "held") ++held;
    if (record.status != "first" && record.status != "stationary") ++moving;
  }
  if (moving > 0 && unscaled == moving) {
    warnings.push_back(
        "no usable road in the whole sequence: the trajectory is UNSCALED (unit steps, "
        "arbitrary scale)");
    return warnings;
  }
  // Runs of unscaled, back-filled or held frames, each reported once.
  size_t begin = 0;
  while (begin < records.size()) {
    const std::string& status = records[begin].status;
    if (status != "unscaled" && status != "held" && status != "backfilled" &&
        status != "pair_fixes") {
      ++begin;
      continue;
    }
    size_t end = begin;
    while (end + 1 < records.size() && records[end + 1].status == status) ++end;
    const std::string span = FrameSpan(records[begin].index, records[end].index);
    if (status == "unscaled") {
      warnings.push_back("no scale yet in " + span + ": unscaled there (unit steps)");
    } else if (status == "backfilled" && end - begin + 1 >= 10) {
      warnings.push_back("no scale yet in " + span +
                         ": back-filled there from the first scale and the parallax");
    } else if (status == "pair_fixes") {
      warnings.push_back("too little road for the map's own scale in " + span +
                         ": scaled there by the keyframe pairs' own road fixes");
    } else if (status == "held" && end - begin + 1 >= 10) {
      warnings.push_back("no usable road in " + span + ": the last scale was held there");
    }
    begin = end + 1;
  }
  if (held > 0 && moving > 0 && held * 2 > moving) {
    warnings.push_back(std::to_string(held) + " of " + std::to_string(moving) +
                       " moving frames held the last scale");
  }
  return warnings;
}

std::vector<FrameSeries> RunFrameSeries(const RunReportData& data) {
  const size_t n = data.records.size();
  const std::vector<std::string> columns = SplitCsv(data.scale_diagnostics_header);
  const auto column = [&](const std::string& name) {
    std::vector<double> values(n, kNaN);
    for (size_t c = 0; c < columns.size(); ++c) {
      if (columns[c] != name) continue;
      for (size_t i = 0; i < n; ++i) {
        const std::vector<std::string> fields = SplitCsv(data.records[i].scale_diagnostics_csv);
        if (c < fields.size()) values[i] = ParseOrNaN(fields[c]);
      }
    }
    return values;
  };
  const auto per_frame = [&](auto get) {
    std::vector<double> values(n);
    for (size_t i = 0; i < n; ++i) values[i] = get(data.records[i]);
    return values;
  };
  std::vector<FrameSeries> series;
  // The keyframe back end's columns (MappedFrameCsvHeader) or the road scale source's.
  const bool keyframe_mode = std::find(columns.begin(), columns.end(), "keyframe") != columns.end();
  const bool road = !columns.empty() && !keyframe_mode;
  if (road) {
    series.push_back({"scale_raw", FrameSeriesKind::kScale, column("road_raw_scale")});
    series.push_back({"scale_filtered", FrameSeriesKind::kScale, column("road_scale")});
  } else {
    series.push_back(
        {"scale_filtered", FrameSeriesKind::kScale,
         per_frame([](const FrameRecord& r) { return r.scale_valid ? r.step_length_m : kNaN; })});
  }
  if (data.gt_world_from_cam.size() == n && n > 0) {
    std::vector<double> truth(n, kNaN);
    for (size_t i = 1; i < n; ++i) {
      truth[i] = (data.gt_world_from_cam[i - 1].inverse() * data.gt_world_from_cam[i])
                     .translation()
                     .norm();
    }
    series.push_back({"scale_true", FrameSeriesKind::kScale, truth});
  }
  if (keyframe_mode) {
    series.push_back({"landmarks_seen", FrameSeriesKind::kCount, column("landmarks_seen")});
    series.push_back(
        {"window_road_landmarks", FrameSeriesKind::kCount, column("window_road_landmarks")});
    series.push_back({"road_points_marked", FrameSeriesKind::kCount, column("road_points")});
    series.push_back({"road_tracks", FrameSeriesKind::kCount, per_frame([](const FrameRecord& r) {
                        return r.road_tracks >= 0 ? r.road_tracks : kNaN;
                      })});
  }
  if (road) {
    series.push_back({"points_triangulated", FrameSeriesKind::kCount, column("road_triangulated")});
    series.push_back({"points_road_mask", FrameSeriesKind::kCount, column("road_preselected")});
    series.push_back({"points_vote", FrameSeriesKind::kCount, column("road_after_vote")});
    series.push_back(
        {"points_model_check", FrameSeriesKind::kCount, column("road_after_model_check")});
    series.push_back({"ransac_inliers", FrameSeriesKind::kCount, column("road_ransac_inliers")});
  }
  series.push_back({"ms_load", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.load_ms; })});
  series.push_back({"ms_segmentation", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.segmentation_ms; })});
  series.push_back({"ms_tracking", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.tracking_ms; })});
  series.push_back({"ms_detection", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.detection_ms; })});
  series.push_back({"ms_motion", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.motion_ms; })});
  series.push_back({"ms_scale", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.scale_ms; })});
  // CPU time of each thread's work on the frame: on a shared machine the wall times above
  // include the waits for a core.
  series.push_back({"cpu_ms_segmentation", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.segmentation_cpu_ms; })});
  series.push_back({"cpu_ms_frontend", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.frontend_cpu_ms; })});
  series.push_back({"cpu_ms_scale_and_pose", FrameSeriesKind::kMilliseconds,
                    per_frame([](const FrameRecord& r) { return r.scale_cpu_ms; })});
  series.push_back({"segmented", FrameSeriesKind::kOther,
                    per_frame([](const FrameRecord& r) { return r.segmented ? 1.0 : 0.0; })});
  if (keyframe_mode) {
    // NaN in the frames that are no keyframes: the timing table then gives the adjustment's
    // time per keyframe.
    std::vector<double> bundle_adjustment = column("ba_ms");
    const std::vector<double> keyframe = column("keyframe");
    for (size_t i = 0; i < n; ++i) {
      if (keyframe[i] != 1.0) bundle_adjustment[i] = kNaN;
    }
    series.push_back({"ms_bundle_adjustment", FrameSeriesKind::kMilliseconds, bundle_adjustment});
    series.push_back({"keyframe", FrameSeriesKind::kOther, keyframe});
    series.push_back({"pair_scale", FrameSeriesKind::kOther, column("pair_scale")});
  }
  if (road) series.push_back({"plane_h", FrameSeriesKind::kOther, column("road_plane_h")});
  series.push_back({"tracks", FrameSeriesKind::kOther,
                    per_frame([](const FrameRecord& r) { return double(r.num_tracks); })});
  series.push_back({"inliers", FrameSeriesKind::kOther,
                    per_frame([](const FrameRecord& r) { return double(r.num_inliers); })});
  series.push_back({"dropped_dynamic", FrameSeriesKind::kOther,
                    per_frame([](const FrameRecord& r) { return double(r.num_dropped_dynamic); })});
  return series;
}

std::optional<TrajectoryEvaluation> EvaluateRun(const RunReportData& data) {
  if (data.gt_world_from_cam.size() != data.est_world_from_cam.size() ||
      data.est_world_from_cam.size() < 2) {
    return std::nullopt;
  }
  return EvaluateTrajectory(data.gt_world_from_cam, data.est_world_from_cam);
}

std::vector<std::string> WriteRunReport(const std::string& out_dir, const RunReportData& data,
                                        const std::optional<TrajectoryEvaluation>& evaluation) {
  std::vector<std::string> written;
  if (evaluation) {
    const std::string path = (std::filesystem::path(out_dir) / "metrics.json").string();
    WriteFileAtomically(path, FormatMetricsJson(*evaluation));
    written.push_back(path);
  }
  HtmlReportInput input;
  input.title = data.title;
  input.inputs = data.inputs;
  input.warnings = ScaleWarnings(data.records);
  input.est_world_from_cam = data.est_world_from_cam;
  if (evaluation) input.gt_world_from_cam = data.gt_world_from_cam;
  input.evaluation = evaluation;
  input.series = RunFrameSeries(data);
  for (size_t i = 0; i < data.records.size(); ++i) {
    input.frame_status.push_back(data.records[i].status);
    if (data.records[i].keyframe) input.keyframes.push_back(i);
  }
  input.wall_time_s = data.wall_time_s;
  const std::string path = (std::filesystem::path(out_dir) / "report.html").string();
  WriteHtmlReport(path, input);
  written.push_back(path);
  return written;
}

}  // namespace roadscale
