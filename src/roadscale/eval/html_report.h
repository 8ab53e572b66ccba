#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "roadscale/eval/trajectory_evaluation.h"
#include "roadscale/geometry/rigid3.h"

namespace roadscale {

// Where a per-frame series appears in the report.
enum class FrameSeriesKind {
  kScale,         // "Scale per frame", one figure for all (scale_raw, scale_filtered, scale_true)
  kCount,         // "Points per stage", one figure for all (points_road_mask, ..., ransac_inliers)
  kMilliseconds,  // a stage's time per frame: the timing table and figure (ms_segmentation, ...)
  kOther,         // the per-frame summary table only (plane_h, tracks, ...)
};

// One per-frame quantity of a run, as a column of frames.csv: values[i] is frame i's, NaN
// where frame i has none. Every series, whatever its kind, is also listed in the summary
// table (frames with a value, min, mean, max).
struct FrameSeries {
  std::string name;
  FrameSeriesKind kind = FrameSeriesKind::kOther;
  std::vector<double> values;
};

// Everything the report shows. Only the estimate is required; each section says what is
// missing when its input is (no ground truth, no series, no status, 1 frame).
struct HtmlReportInput {
  std::string title;  // e.g. "roadscale run: KITTI 00"
  // What was run, as "name: value" lines in this order (sequence, camera, config, model, h0).
  std::vector<std::pair<std::string, std::string>> inputs;
  // Shown above everything else (e.g. "no usable road in frames 310-420: unscaled there").
  std::vector<std::string> warnings;
  std::vector<Rigid3d> est_world_from_cam;  // the estimate, one pose per frame
  std::vector<Rigid3d> gt_world_from_cam;   // the ground truth; empty when there is none
  // The metrics (EvaluateTrajectory of the paired poses); empty without ground truth.
  std::optional<TrajectoryEvaluation> evaluation;
  std::vector<FrameSeries> series;
  // One per frame ("ok", "held", "stationary", ...), counted in order of first appearance;
  // may be empty.
  std::vector<std::string> frame_status;
  // Frames that were keyframes of the run's map (indices into the estimate), marked on the
  // top view; empty for the frame-to-frame host.
  std::vector<size_t> keyframes;
  // The run's wall-clock time, for the end-to-end frame rate (stages overlap on threads, so
  // it is not the sum of the stage times).
  std::optional<double> wall_time_s;
};

// The report as one self-contained HTML page: CSS and the figures (SVG drawn with Cairo,
// plots.h) inline, no script, no external reference. Sections: header (title, inputs,
// warnings, headline metrics: t_err %, r_err deg/m, ATE se3, length ratio), trajectory top
// view with the metrics table, scale per frame, status per frame, points per stage, KITTI
// error vs length, timing (mean / median / p90 / max ms per stage, fps), per-frame summary.
// Every text given is HTML-escaped. Throws Error when a figure cannot be drawn.
std::string RenderHtmlReport(const HtmlReportInput& input);

// Writes RenderHtmlReport(input) to `path` atomically: a temporary file beside it, synced,
// then renamed, so `path` holds either the old report or the whole new one. Creates missing
// parent folders. Throws Error naming the file when it cannot be written.
void WriteHtmlReport(const std::string& path, const HtmlReportInput& input);

}  // namespace roadscale
