#pragma once

#include <optional>
#include <string>
#include <vector>

namespace roadscale::batch {

// DIR/<name>/batch_drive.json: what the batch ran for a drive and how it ended, written when
// the drive's process has ended. It makes resuming possible (a drive whose record says it
// finished with the same fingerprint, and whose outputs are all there, is not run again) and
// gives the summary the drive's wall time.
inline constexpr char kDriveRecordFile[] = "batch_drive.json";
// The drive's `roadscale run` output (stdout and stderr), beside its outputs.
inline constexpr char kDriveLogFile[] = "run.log";

struct DriveRecord {
  std::string name;
  std::string fingerprint;             // DriveFingerprint
  std::vector<std::string> arguments;  // run's arguments
  int exit_status = 0;                 // the process's; 128 + N when signal N ended it
  std::string error;                   // its last "roadscale: error: ..." line, when it failed
  double wall_s = 0.0;                 // the process's wall time
  // Stopped by the batch's own Ctrl-C or SIGTERM, not failed: the same command runs it again.
  bool interrupted = false;
  std::vector<std::string> outputs;  // run's output files present when it ended
};

// Writes the record into `drive_dir` (through a temporary file renamed over it, so that a
// reader never sees half a record). Throws Error naming the file when it cannot be written.
void WriteDriveRecord(const std::string& drive_dir, const DriveRecord& record);

// The record in `drive_dir`; nothing when there is none. Throws Error naming the file when it
// is not a record (a record nobody can read must not silently count as "not run").
std::optional<DriveRecord> ReadDriveRecord(const std::string& drive_dir);

// Removes the record, so that a drive that is being rerun never looks finished. Throws Error
// naming the file when it cannot be removed.
void RemoveDriveRecord(const std::string& drive_dir);

// Which of run's output files (poses_kitti.txt, poses_tum.txt, frames.csv, config_used.yaml,
// report.html, metrics.json, gt_poses_kitti.txt) are in `drive_dir`.
std::vector<std::string> RunOutputsIn(const std::string& drive_dir);

// True when the drive in `drive_dir` needs no run: its record says it finished (status 0)
// with `fingerprint`, it lists every output each run writes (poses_kitti.txt, poses_tum.txt,
// frames.csv, config_used.yaml, report.html), every output it lists is still there, and they
// agree: as many whole rows in poses_kitti.txt as in poses_tum.txt (and gt_poses_kitti.txt),
// one more in frames.csv (its header). A record that cannot be read means "run again".
bool IsDriveFinished(const std::string& drive_dir, const std::string& fingerprint);

// The text of the last "roadscale: error: ..." (or "roadscale: internal error: ...") line of
// a drive's log; empty when there is none.
std::string LastErrorLine(const std::string& log_path);

}  // namespace roadscale::batch
