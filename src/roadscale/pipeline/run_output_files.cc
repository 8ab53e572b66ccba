#include "roadscale/pipeline/run_output_files.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "roadscale/io/trajectory_io.h"
#include "roadscale/util/error.h"
#include "roadscale/util/line_file.h"

namespace roadscale {
namespace {

std::ofstream OpenOutput(const std::string& path) {
  std::ofstream file(path, std::ios::out | std::ios::trunc);
  if (!file) ThrowFileError(path, "cannot create the file");
  return file;
}

}  // namespace

RunOutputFiles::RunOutputFiles(const std::string& out_dir, const std::string& diagnostics_header)
    : diagnostics_header_(diagnostics_header) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error || !std::filesystem::is_directory(out_dir)) {
    ThrowFileError(out_dir, "cannot create the output folder" +
                                (error ? " (" + error.message() + ")" : std::string()));
  }
  poses_path_ = (std::filesystem::path(out_dir) / "poses_kitti.txt").string();
  tum_path_ = (std::filesystem::path(out_dir) / "poses_tum.txt").string();
  records_path_ = (std::filesystem::path(out_dir) / "frames.csv").string();
  poses_ = OpenOutput(poses_path_);
  tum_ = OpenOutput(tum_path_);
  records_ = OpenOutput(records_path_);
  WriteWholeLine(
      records_, records_path_,
      FrameRecordCsvHeader() + (diagnostics_header_.empty() ? "" : "," + diagnostics_header_));
}

void RunOutputFiles::Write(const FrameRecord& record, const Rigid3d& world_from_cam) {
  WriteWholeLine(poses_, poses_path_, FormatKittiRow(world_from_cam));
  WriteWholeLine(tum_, tum_path_, FormatTumRow(record.timestamp, world_from_cam));
  std::string row = FormatFrameRecordCsv(record);
  if (!diagnostics_header_.empty()) {
    row +=
        record.scale_diagnostics_csv.empty()
            ? std::string(
                  std::count(diagnostics_header_.begin(), diagnostics_header_.end(), ',') + 1, ',')
            : "," + record.scale_diagnostics_csv;
  }
  WriteWholeLine(records_, records_path_, row);
}

}  // namespace roadscale
