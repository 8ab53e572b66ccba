#include "roadscale/batch/drive_record.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include <nlohmann/json.hpp>

#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"

namespace roadscale::batch {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string RecordPath(const std::string& drive_dir) {
  return (fs::path(drive_dir) / kDriveRecordFile).string();
}

// The outputs every finished run writes (metrics.json and gt_poses_kitti.txt need ground truth).
constexpr const char* kOutputsOfEveryRun[] = {"poses_kitti.txt", "poses_tum.txt", "frames.csv",
                                              "config_used.yaml", "report.html"};

// The number of rows of the file, each ended by '\n'; nothing when it cannot be read or its
// last row is cut.
std::optional<size_t> WholeRows(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (!text.empty() && text.back() != '\n') return std::nullopt;
  return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

void WriteDriveRecord(const std::string& drive_dir, const DriveRecord& record) {
  Json json;
  json["name"] = record.name;
  json["fingerprint"] = record.fingerprint;
  json["arguments"] = record.arguments;
  json["exit_status"] = record.exit_status;
  json["error"] = record.error;
  json["wall_s"] = record.wall_s;
  json["interrupted"] = record.interrupted;
  json["outputs"] = record.outputs;
  WriteFileAtomically(RecordPath(drive_dir), json.dump(2) + '\n');
}

std::optional<DriveRecord> ReadDriveRecord(const std::string& drive_dir) {
  const std::string path = RecordPath(drive_dir);
  if (!fs::exists(path)) return std::nullopt;
  try {
    const Json json = Json::parse(ReadInputFile(path, "drive record"));
    DriveRecord record;
    record.name = json.at("name").get<std::string>();
    record.fingerprint = json.at("fingerprint").get<std::string>();
    record.arguments = json.at("arguments").get<std::vector<std::string>>();
    record.exit_status = json.at("exit_status").get<int>();
    record.error = json.at("error").get<std::string>();
    record.wall_s = json.at("wall_s").get<double>();
    // Records written before the field existed were never of an interrupted drive's.
    record.interrupted = json.value("interrupted", false);
    record.outputs = json.at("outputs").get<std::vector<std::string>>();
    return record;
  } catch (const nlohmann::json::exception& e) {
    ThrowFileError(path, std::string("not a drive record (") + e.what() +
                             "); remove it to run the drive again");
  }
}

void RemoveDriveRecord(const std::string& drive_dir) {
  std::error_code error;
  fs::remove(RecordPath(drive_dir), error);
  if (error) {
    ThrowFileError(RecordPath(drive_dir),
                   "cannot remove the previous drive record (" + error.message() + ")");
  }
}

std::vector<std::string> RunOutputsIn(const std::string& drive_dir) {
  std::vector<std::string> present;
  for (const char* name : {"poses_kitti.txt", "poses_tum.txt", "frames.csv", "config_used.yaml",
                           "report.html", "metrics.json", "gt_poses_kitti.txt"}) {
    if (fs::is_regular_file(fs::path(drive_dir) / name)) present.push_back(name);
  }
  return present;
}

bool IsDriveFinished(const std::string& drive_dir, const std::string& fingerprint) {
  std::optional<DriveRecord> record;
  try {
    record = ReadDriveRecord(drive_dir);
  } catch (const Error&) {
    return false;  // a record nobody can read proves nothing: the drive runs again
  }
  if (!record || record->exit_status != 0 || record->fingerprint != fingerprint) return false;
  const auto listed = [&record](const std::string& name) {
    return std::find(record->outputs.begin(), record->outputs.end(), name) != record->outputs.end();
  };
  // A record cut down to fewer outputs must not make an unfinished drive look finished.
  for (const char* name : kOutputsOfEveryRun) {
    if (!listed(name)) return false;
  }
  for (const std::string& output : record->outputs) {
    if (!fs::is_regular_file(fs::path(drive_dir) / output)) return false;
  }
  // One row per frame in each, whole rows only: a truncated file is no finished run.
  const fs::path dir(drive_dir);
  const std::optional<size_t> poses = WholeRows(dir / "poses_kitti.txt");
  if (!poses || *poses == 0 || WholeRows(dir / "poses_tum.txt") != poses ||
      WholeRows(dir / "frames.csv") != *poses + 1) {
    return false;
  }
  return !listed("gt_poses_kitti.txt") || WholeRows(dir / "gt_poses_kitti.txt") == poses;
}

std::string LastErrorLine(const std::string& log_path) {
  std::ifstream log(log_path);
  const std::string prefix = "roadscale: ";
  std::string line;
  std::string last;
  while (std::getline(log, line)) {
    if (line.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = line.substr(prefix.size());
    if (rest.compare(0, 7, "error: ") == 0) last = rest.substr(7);
    if (rest.compare(0, 16, "internal error: ") == 0) last = rest;
  }
  return last;
}

}  // namespace roadscale::batch
