#include "roadscale/batch/batch_folder.h"

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "roadscale/batch/drive_record.h"
#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"

namespace roadscale::batch {
namespace {

namespace fs = std::filesystem;

std::string ListPath(const std::string& dir) { return (fs::path(dir) / "batch.json").string(); }

}  // namespace

std::string DriveFolder(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

void WriteDriveList(const std::string& dir, const std::vector<std::string>& names) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    ThrowFileError(dir, "cannot create the batch's output folder" +
                            (error ? " (" + error.message() + ")" : std::string()));
  }
  nlohmann::ordered_json json;
  json["drives"] = names;
  WriteFileAtomically(ListPath(dir), json.dump(2) + '\n');
}

std::vector<std::string> DriveNamesIn(const std::string& dir) {
  if (!fs::is_directory(dir)) ThrowFileError(dir, "not a batch output folder (no such folder)");
  if (fs::exists(ListPath(dir))) {
    try {
      return nlohmann::json::parse(ReadInputFile(ListPath(dir), "batch list"))
          .at("drives")
          .get<std::vector<std::string>>();
    } catch (const nlohmann::json::exception& e) {
      ThrowFileError(ListPath(dir), std::string("not a list of drives (") + e.what() + ")");
    }
  }
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory() && fs::exists(entry.path() / kDriveRecordFile)) {
      names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace roadscale::batch
