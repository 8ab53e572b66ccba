#include "output_folder.h"

#include <filesystem>
#include <system_error>

#include "roadscale/util/error.h"

namespace roadscale::cli {

FolderLock PrepareOutputFolder(const std::string& out, const std::string& command) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::create_directories(out, error);
  if (error || !fs::is_directory(out)) {
    ThrowFileError(out, "cannot create the output folder" +
                            (error ? " (" + error.message() + ")" : std::string()));
  }
  FolderLock lock(out, command);
  for (const char* name : {"poses_kitti.txt", "poses_tum.txt", "frames.csv", "config_used.yaml",
                           "report.html", "metrics.json", "gt_poses_kitti.txt", "rescale.csv"}) {
    const fs::path path = fs::path(out) / name;
    fs::remove(path, error);
    if (error) {
      ThrowFileError(path.string(),
                     "cannot remove the previous run's file (" + error.message() + ")");
    }
  }
  return lock;
}

}  // namespace roadscale::cli
