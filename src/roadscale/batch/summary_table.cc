#include "roadscale/batch/summary_table.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "roadscale/batch/batch_folder.h"
#include "roadscale/batch/drive_record.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"

namespace roadscale::batch {
namespace {

namespace fs = std::filesystem;

std::optional<double> NumberAt(const nlohmann::json& json, const nlohmann::json::json_pointer& at) {
  if (!json.contains(at) || json.at(at).is_null()) return std::nullopt;
  return json.at(at).get<double>();
}

// frames.csv's row count and status shares.
void ReadFrameStatuses(const std::string& path, DriveRow* row) {
  std::istringstream csv(ReadInputFile(path, "frames file"));
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> header;
  std::istringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  const auto status_column = std::find(header.begin(), header.end(), "status") - header.begin();
  if (status_column == static_cast<long>(header.size())) {
    ThrowFileError(path, 1, "no status column in the header");
  }
  int frames = 0;
  int held = 0;
  int unscaled = 0;
  for (int line_number = 2; std::getline(csv, line); ++line_number) {
    std::istringstream fields(line);
    std::string field;
    for (long column = 0; column <= status_column; ++column) {
      if (!std::getline(fields, field, ',')) ThrowFileError(path, line_number, "no status field");
    }
    ++frames;
    held += field == "held";
    unscaled += field == "unscaled";
  }
  if (frames == 0) ThrowFileError(path, "no frames");
  row->frames = frames;
  row->held_share = static_cast<double>(held) / frames;
  row->unscaled_share = static_cast<double>(unscaled) / frames;
  row->scaled_share = static_cast<double>(frames - held - unscaled) / frames;
}

double PathLength(const std::string& poses_path) {
  const Trajectory trajectory = ReadKittiTrajectory(poses_path);
  double length = 0.0;
  for (size_t i = 1; i < trajectory.size(); ++i) {
    length += (trajectory.world_from_cam[i].translation() -
               trajectory.world_from_cam[i - 1].translation())
                  .norm();
  }
  return length;
}

void ReadMetrics(const std::string& path, DriveRow* row) {
  using Pointer = nlohmann::json::json_pointer;
  try {
    const nlohmann::json metrics = nlohmann::json::parse(ReadInputFile(path, "metrics file"));
    row->t_err_pct = NumberAt(metrics, Pointer("/kitti/t_err_pct"));
    row->r_err_deg_per_m = NumberAt(metrics, Pointer("/kitti/r_err_deg_per_m"));
    if (row->r_err_deg_per_m) row->r_err_deg_per_100m = 100.0 * *row->r_err_deg_per_m;
    row->ate_se3_m = NumberAt(metrics, Pointer("/ate_m/se3"));
    row->ate_sim3_m = NumberAt(metrics, Pointer("/ate_m/sim3"));
    row->length_ratio = NumberAt(metrics, Pointer("/length_ratio"));
  } catch (const nlohmann::json::exception& e) {
    ThrowFileError(path, std::string("not a metrics.json (") + e.what() + ")");
  }
}

}  // namespace

const std::vector<SummaryColumn>& SummaryColumns() {
  static const std::vector<SummaryColumn> columns = {
      {"frames", "frames", 0, &DriveRow::frames},
      {"length_m", "length (m)", 1, &DriveRow::length_m},
      {"t_err_pct", "t_err (%)", 2, &DriveRow::t_err_pct},
      {"r_err_deg_per_100m", "r_err (deg/100 m)", 3, &DriveRow::r_err_deg_per_100m},
      {"r_err_deg_per_m", "r_err (deg/m)", 5, &DriveRow::r_err_deg_per_m},
      {"ate_se3_m", "ATE se3 (m)", 3, &DriveRow::ate_se3_m},
      {"ate_sim3_m", "ATE sim3 (m)", 3, &DriveRow::ate_sim3_m},
      {"length_ratio", "length ratio", 4, &DriveRow::length_ratio},
      {"scaled_share", "scaled", 3, &DriveRow::scaled_share},
      {"held_share", "held", 3, &DriveRow::held_share},
      {"unscaled_share", "unscaled", 3, &DriveRow::unscaled_share},
      {"frames_per_s", "frames/s", 1, &DriveRow::frames_per_s},
  };
  return columns;
}

DriveRow ReadDriveRow(const std::string& drive_dir, const std::string& name) {
  DriveRow row;
  row.name = name;
  row.report = name + "/report.html";
  const fs::path dir(drive_dir);
  ReadFrameStatuses((dir / "frames.csv").string(), &row);
  row.length_m = PathLength((dir / "poses_kitti.txt").string());
  const fs::path metrics = dir / "metrics.json";
  row.ground_truth = fs::exists(metrics);
  if (row.ground_truth) ReadMetrics(metrics.string(), &row);
  const std::optional<DriveRecord> record = ReadDriveRecord(drive_dir);
  // No process runs in less than a millisecond: a shorter wall time is a damaged record, and
  // its frames/s would print with hundreds of digits.
  if (record && record->wall_s >= 1e-3) row.frames_per_s = *row.frames / record->wall_s;
  return row;
}

BatchSummary SummarizeDrives(const std::string& dir, const std::vector<std::string>& names) {
  BatchSummary summary;
  for (const std::string& name : names) {
    const std::string drive_dir = DriveFolder(dir, name);
    // A damaged record or output is that drive's problem, listed with it: the others are
    // still summarised.
    try {
      const std::optional<DriveRecord> record = ReadDriveRecord(drive_dir);
      if (!record) {
        summary.unfinished.push_back({name, "not run"});
      } else if (record->exit_status != 0 && record->interrupted) {
        summary.unfinished.push_back({name, "interrupted: the same command runs it again"});
      } else if (record->exit_status != 0) {
        summary.unfinished.push_back(
            {name, "failed (exit status " + std::to_string(record->exit_status) + ")" +
                       (record->error.empty() ? std::string() : ": " + record->error)});
      } else {
        summary.rows.push_back(ReadDriveRow(drive_dir, name));
      }
    } catch (const Error& error) {
      summary.unfinished.push_back({name, std::string("damaged: ") + error.what()});
    }
  }
  DriveRow mean;
  mean.name = "mean";
  for (const SummaryColumn& column : SummaryColumns()) {
    double sum = 0.0;
    int count = 0;
    for (const DriveRow& row : summary.rows) {
      if (row.ground_truth && row.*column.value) {
        sum += *(row.*column.value);
        ++count;
      }
    }
    if (count > 0) mean.*column.value = sum / count;
  }
  for (const DriveRow& row : summary.rows) summary.mean_over += row.ground_truth;
  if (summary.mean_over > 0) summary.mean = mean;
  return summary;
}

}  // namespace roadscale::batch
