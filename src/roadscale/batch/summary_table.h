#pragma once

#include <optional>
#include <string>
#include <vector>

namespace roadscale::batch {

// One finished drive's row of the batch summary, read from its folder. Values a drive
// without ground truth (no metrics.json) cannot have, or its metrics.json gives as null
// (a drive too short for a KITTI segment), are unset.
struct DriveRow {
  std::string name;
  std::string report;  // the drive's report.html, relative to the batch folder
  bool ground_truth = false;
  std::optional<double> frames;
  std::optional<double> length_m;  // the estimated trajectory's path length
  std::optional<double> t_err_pct;
  std::optional<double> r_err_deg_per_100m;
  std::optional<double> r_err_deg_per_m;
  std::optional<double> ate_se3_m;
  std::optional<double> ate_sim3_m;
  std::optional<double> length_ratio;
  std::optional<double> scaled_share;  // frames with a metric step: not held, not unscaled
  std::optional<double> held_share;    // frames whose step reused the last scale
  std::optional<double> unscaled_share;
  std::optional<double> frames_per_s;  // frames over the drive process's wall time
};

// A column of the summary: `key` is the CSV and JSON name, the metrics.json key where the
// value comes from there (`ate_m.se3` becomes ate_se3_m); `header` the tables' heading.
struct SummaryColumn {
  const char* key;
  const char* header;
  int decimals;
  std::optional<double> DriveRow::*value;
};
const std::vector<SummaryColumn>& SummaryColumns();

// A drive of the batch without a row: never run, failed, or interrupted.
struct UnfinishedDrive {
  std::string name;
  std::string reason;
};

struct BatchSummary {
  std::vector<DriveRow> rows;
  std::vector<UnfinishedDrive> unfinished;
  // The mean of each column over the rows with ground truth (each over those rows where it is
  // set); unset when no row has ground truth.
  std::optional<DriveRow> mean;
  int mean_over = 0;  // rows with ground truth
};

// The row of the finished drive in `drive_dir` (folder name `name`): frames.csv (frames, the
// status shares), poses_kitti.txt (length), metrics.json (the KITTI metric, ATE, length ratio;
// `r_err_deg_per_100m` is 100 times its r_err_deg_per_m) and the drive record (frames/s).
// Throws Error naming a file that is missing or malformed.
DriveRow ReadDriveRow(const std::string& drive_dir, const std::string& name);

// The summary of the drives `names` in the batch folder `dir`: a row for each drive whose
// record says it finished, the others listed as unfinished with the reason (a drive whose
// record or outputs cannot be read as "damaged: " and the error naming the file).
BatchSummary SummarizeDrives(const std::string& dir, const std::vector<std::string>& names);

}  // namespace roadscale::batch
