#include "roadscale/batch/batch_folder.h"

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "roadscale/batch/drive_record.h"
#include "roadscale/batch/manifest.h"
#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"

namespace roadscale::batch {
namespace {

namespace fs = std::filesystem;

std::string ListPath(const std::string& dir) { return (fs::path(dir) / "batch.json").string(); }

bool IsDriveName(const std::string& name) {
  try {
    CheckDriveName(name, name);
  } catch (const Error&) {
    return false;
  }
  return true;
}

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
    std::vector<std::string> names;
    try {
      names = nlohmann::json::parse(ReadInputFile(ListPath(dir), "batch list"))
                  .at("drives")
                  .get<std::vector<std::string>>();
    } catch (const nlohmann::json::exception& e) {
      ThrowFileError(ListPath(dir), std::string("not a list of drives (") + e.what() + ")");
    }
    // The names become paths and text of the summary: a name a manifest could not hold
    // ("../../../etc", HTML) means the file was not written by a batch.
    for (const std::string& name : names) {
      try {
        CheckDriveName(name, "drive '" + name + "'");
      } catch (const Error& e) {
        ThrowFileError(ListPath(dir), e.what());
      }
    }
    return names;
  }
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && fs::exists(entry.path() / kDriveRecordFile) && IsDriveName(name)) {
      names.push_back(name);
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace roadscale::batch
