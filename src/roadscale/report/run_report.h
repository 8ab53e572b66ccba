#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "roadscale/eval/html_report.h"
#include "roadscale/eval/trajectory_evaluation.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/pipeline/sequential_pipeline.h"

namespace roadscale {

// What a finished run leaves for its report. The records and poses are the run's own,
// referred to, not copied (a long drive's records are megabytes): they must outlive it.
struct RunReportData {
  RunReportData(const std::vector<FrameRecord>& records,
                const std::vector<Rigid3d>& est_world_from_cam,
                const std::vector<Rigid3d>& gt_world_from_cam)
      : records(records),
        est_world_from_cam(est_world_from_cam),
        gt_world_from_cam(gt_world_from_cam) {}

  std::string title;
  std::vector<std::pair<std::string, std::string>> inputs;
  const std::vector<FrameRecord>& records;         // one per frame, in order
  std::string scale_diagnostics_header;            // the scale source's frames.csv columns
  const std::vector<Rigid3d>& est_world_from_cam;  // one per record
  const std::vector<Rigid3d>& gt_world_from_cam;   // one per record, or empty
  std::optional<double> wall_time_s;
};

// Warnings about the trajectory's scale for the user and the report: frames that were
// unscaled (no valid scale yet), and runs of held frames, e.g. "no usable road in frames
// 310-420: the last scale was held there". Empty when every step was scaled.
std::vector<std::string> ScaleWarnings(const std::vector<FrameRecord>& records);

// The report's per-frame series: scale (raw, filtered, and the true step length when the
// ground truth is given), points after each scale stage, ms per stage, plane height, tracks.
std::vector<FrameSeries> RunFrameSeries(const RunReportData& data);

// The evaluation of the run against its ground truth; nothing without ground truth or with
// fewer than 2 frames.
std::optional<TrajectoryEvaluation> EvaluateRun(const RunReportData& data);

// Writes OUT/metrics.json (`roadscale eval --json`'s shape, when `evaluation` is given) and
// OUT/report.html. Returns the paths written.
std::vector<std::string> WriteRunReport(const std::string& out_dir, const RunReportData& data,
                                        const std::optional<TrajectoryEvaluation>& evaluation);

}  // namespace roadscale
