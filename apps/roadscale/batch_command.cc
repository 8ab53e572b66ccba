// `roadscale batch`: many drives, each run exactly as `roadscale run` would run it (as a
// process of its own), N at a time on this machine or as a Slurm job array, resumable, with
// a per-drive summary table like the paper's.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "roadscale/batch/batch_folder.h"
#include "roadscale/batch/drive_record.h"
#include "roadscale/batch/drive_run.h"
#include "roadscale/batch/manifest.h"
#include "roadscale/batch/slurm_script.h"
#include "roadscale/batch/summary_files.h"
#include "roadscale/batch/summary_table.h"
#include "roadscale/util/error.h"
#include "roadscale/util/folder_lock.h"

#include "commands.h"
#include "drive_processes.h"
#include "interrupt.h"
#include "run_command.h"

namespace roadscale::cli {
namespace {

namespace fs = std::filesystem;

struct BatchArguments {
  std::string manifest;
  std::string kitti_root;
  std::string sequences;
  std::string out;
  int jobs = 1;
  std::optional<long long> only_index;  // signed: CLI11 would wrap -1 round to 2^64 - 1
  std::string summarize;
  bool slurm = false;
  bool submit = false;
  std::string partition;
  std::string time;
  int cpus_per_task = 2;
  std::vector<std::string> sbatch_options;
};

std::string Absolute(const std::string& path) {
  return fs::absolute(path).lexically_normal().string();
}

// The words that name the batch's drives on a command line, for the Slurm tasks.
std::vector<std::string> BatchInputWords(const BatchArguments& arguments) {
  if (!arguments.manifest.empty()) return {"--manifest", Absolute(arguments.manifest)};
  return {"--kitti-root", Absolute(arguments.kitti_root), "--sequences", arguments.sequences};
}

// The binary that is running, so that every drive runs the same roadscale.
std::string SelfPath() { return fs::read_symlink("/proc/self/exe").string(); }

std::vector<std::string> Summarize(const std::string& dir) {
  return batch::WriteSummaryFiles(dir, batch::SummarizeDrives(dir, batch::DriveNamesIn(dir)));
}

batch::SlurmOptions SlurmOptionsOf(const BatchArguments& arguments, size_t drives) {
  batch::SlurmOptions options;
  options.roadscale = SelfPath();
  options.batch_input = BatchInputWords(arguments);
  options.out = Absolute(arguments.out);
  options.drives = drives;
  options.partition = arguments.partition;
  options.time = arguments.time;
  options.cpus_per_task = arguments.cpus_per_task;
  options.sbatch_options = arguments.sbatch_options;
  return options;
}

void WriteSlurm(const BatchArguments& arguments, const batch::BatchManifest& manifest) {
  const batch::SlurmOptions options = SlurmOptionsOf(arguments, manifest.drives.size());
  std::vector<std::string> names;
  for (const batch::BatchDrive& drive : manifest.drives) names.push_back(drive.name);
  batch::WriteDriveList(options.out, names);
  const std::string submit = batch::WriteSlurmScripts(options);
  std::cout << "Wrote:  " << submit << " (and drives.sbatch: " << names.size()
            << " array tasks, summary.sbatch)\n"
            << "The batch folder " << options.out
            << " must be on a filesystem every node of the cluster sees.\n"
            << std::flush;
  if (!arguments.submit) {
    std::cout << "Submit with: " << submit << '\n';
    return;
  }
  const int status = std::system(batch::ShellQuote(submit).c_str());
  if (status != 0) {
    throw Error(submit + ": submitting failed (sbatch's message above; exit status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status) + ")");
  }
}

// One line per event, for a terminal and a log alike: "[3/11] 04: done in 52.1 s".
class Progress {
 public:
  explicit Progress(size_t total) : total_(total) {}
  void Line(const std::string& name, const std::string& text) {
    ++done_;
    std::cout << "[" << done_ << "/" << total_ << "] " << name << ": " << text << std::endl;
  }

 private:
  size_t total_;
  size_t done_ = 0;
};

void FailedBeforeStarting(const std::string& name, const std::string& why, Progress* progress,
                          std::vector<std::string>* failures) {
  progress->Line(name, "FAILED before starting: " + why);
  failures->push_back(name + " (" + why + ")");
}

void RunBatch(const BatchArguments& arguments) {
  if (!arguments.summarize.empty()) {
    if (!arguments.manifest.empty() || !arguments.kitti_root.empty() || !arguments.out.empty()) {
      throw Error("--summarize DIR takes no --manifest, --kitti-root or --out");
    }
    std::optional<FolderLock> lock;  // a missing folder is Summarize's error to report
    if (fs::is_directory(arguments.summarize)) lock.emplace(arguments.summarize, "batch");
    for (const std::string& path : Summarize(arguments.summarize)) {
      std::cout << "Wrote:  " << path << '\n';
    }
    return;
  }
  if (arguments.manifest.empty() == arguments.kitti_root.empty()) {
    throw Error("give exactly one of --manifest FILE and --kitti-root ROOT (or --summarize DIR)");
  }
  if (!arguments.kitti_root.empty() && arguments.sequences.empty()) {
    throw Error("--kitti-root needs --sequences (e.g. 00-10)");
  }
  if (arguments.kitti_root.empty() && !arguments.sequences.empty()) {
    throw Error("--sequences goes with --kitti-root");
  }
  if (arguments.out.empty()) throw Error("--out DIR is required");
  if (arguments.submit && !arguments.slurm) throw Error("--submit goes with --slurm");
  if (arguments.slurm) batch::CheckSlurmOptions(SlurmOptionsOf(arguments, 0));  // before any file
  CheckOption(arguments.jobs >= 1 && arguments.jobs <= 256, "--jobs", "must be 1..256");
  CheckOption(arguments.cpus_per_task >= 1, "--cpus-per-task", "must be at least 1");

  const batch::BatchManifest manifest =
      arguments.manifest.empty()
          ? batch::KittiBatchManifest(arguments.kitti_root, arguments.sequences)
          : batch::ReadBatchManifest(arguments.manifest);
  // The whole batch's files (batch.json, summary.*, slurm/) are written by one process at a
  // time. The tasks of a Slurm array (--only-index) run side by side in the same folder by
  // design: each drive's `roadscale run` locks that drive's folder instead.
  std::optional<FolderLock> lock;
  if (!arguments.only_index) {
    std::error_code error;
    fs::create_directories(arguments.out, error);
    if (error || !fs::is_directory(arguments.out)) {
      ThrowFileError(arguments.out, "cannot create the batch's output folder" +
                                        (error ? " (" + error.message() + ")" : std::string()));
    }
    lock.emplace(arguments.out, "batch");
  }
  if (arguments.slurm) {
    if (arguments.only_index) throw Error("--only-index is what the Slurm tasks run, not --slurm");
    WriteSlurm(arguments, manifest);
    return;
  }

  std::vector<size_t> selected;
  if (arguments.only_index) {
    if (*arguments.only_index < 0 ||
        static_cast<size_t>(*arguments.only_index) >= manifest.drives.size()) {
      throw Error("--only-index " + std::to_string(*arguments.only_index) + ": the batch has " +
                  std::to_string(manifest.drives.size()) + " drives (0.." +
                  std::to_string(manifest.drives.size() - 1) + ")");
    }
    selected.push_back(static_cast<size_t>(*arguments.only_index));
  } else {
    std::vector<std::string> names;
    for (size_t i = 0; i < manifest.drives.size(); ++i) {
      selected.push_back(i);
      names.push_back(manifest.drives[i].name);
    }
    batch::WriteDriveList(arguments.out, names);
  }

  // Finished drives with an unchanged fingerprint are skipped; the others are run. A drive
  // that cannot even start (its folder is a file, its config unreadable) is that drive's
  // failure, listed at the end like the others': it does not stop the batch.
  Progress progress(selected.size());
  std::vector<DriveProcess> processes;
  std::vector<const batch::BatchDrive*> to_run;
  std::vector<std::string> fingerprints;
  std::vector<std::string> failures;
  for (const size_t index : selected) {
    const batch::BatchDrive& drive = manifest.drives[index];
    const std::string dir = batch::DriveFolder(arguments.out, drive.name);
    std::string fingerprint;
    try {
      fingerprint = batch::DriveFingerprint(drive, ROADSCALE_VERSION, DefaultModelPath());
      if (batch::IsDriveFinished(dir, fingerprint)) {
        progress.Line(drive.name, "skipped (finished before with the same config)");
        continue;
      }
      std::error_code error;
      fs::create_directories(dir, error);
      if (error || !fs::is_directory(dir)) {
        ThrowFileError(dir, "cannot create the drive's folder" +
                                (error ? " (" + error.message() + ")" : std::string()));
      }
      batch::RemoveDriveRecord(dir);
    } catch (const Error& error) {
      FailedBeforeStarting(drive.name, error.what(), &progress, &failures);
      continue;
    } catch (const fs::filesystem_error& error) {
      FailedBeforeStarting(drive.name, error.what(), &progress, &failures);
      continue;
    }
    processes.push_back(
        {batch::RunArguments(drive, dir), (fs::path(dir) / batch::kDriveLogFile).string()});
    to_run.push_back(&drive);
    fingerprints.push_back(fingerprint);
  }

  {
    InterruptScope interrupt_scope;
    RunDriveProcesses(
        SelfPath(), processes, arguments.jobs, InterruptScope::interrupted(),
        [&](size_t i) {
          std::cout << "       " << to_run[i]->name << ": started (log " << processes[i].log_path
                    << ")" << std::endl;
        },
        [&](size_t i, const DriveExit& exit) {
          const std::string dir = batch::DriveFolder(arguments.out, to_run[i]->name);
          batch::DriveRecord record;
          record.name = to_run[i]->name;
          record.fingerprint = fingerprints[i];
          record.arguments = processes[i].arguments;
          record.exit_status = exit.status;
          record.error = exit.status == 0 ? "" : batch::LastErrorLine(processes[i].log_path);
          record.wall_s = exit.wall_s;
          record.interrupted = exit.status != 0 && InterruptScope::interrupted();
          record.outputs = batch::RunOutputsIn(dir);
          batch::WriteDriveRecord(dir, record);
          char seconds[32];
          std::snprintf(seconds, sizeof(seconds), "%.1f s", exit.wall_s);
          if (exit.status == 0) {
            progress.Line(record.name, std::string("done in ") + seconds);
          } else if (record.interrupted) {
            // Stopped by the batch's own Ctrl-C or SIGTERM: the same command runs it again.
            progress.Line(record.name, "interrupted after " + std::string(seconds) + " (log " +
                                           processes[i].log_path + ")");
          } else {
            const std::string why = "exit status " + std::to_string(exit.status) +
                                    (record.error.empty() ? std::string() : ": " + record.error);
            progress.Line(record.name, "FAILED after " + std::string(seconds) + " (" + why +
                                           "; log " + processes[i].log_path + ")");
            failures.push_back(record.name + " (" + why + ")");
          }
        });
  }
  if (!arguments.only_index) {
    for (const std::string& path : Summarize(arguments.out))
      std::cout << "Wrote:  " << path << '\n';
  }
  if (InterruptScope::interrupted()) {
    throw Error(
        "interrupted: drives not run or stopped part way are run again by the same "
        "command");
  }
  if (!failures.empty()) {
    std::string list;
    for (const std::string& failure : failures) list += (list.empty() ? "" : "; ") + failure;
    throw Error(std::to_string(failures.size()) + " of " + std::to_string(selected.size()) +
                " drives failed: " + list);
  }
}

}  // namespace

void RegisterBatchCommand(CLI::App& app) {
  auto arguments = std::make_shared<BatchArguments>();
  CLI::App* command = app.add_subcommand(
      "batch",
      "Run many drives, each exactly as `roadscale run` would (a process of its own, outputs "
      "in OUT/<name>/ with its log run.log), N at a time, and write the per-drive table "
      "OUT/summary.{md,csv,json,html} (mean over the drives with ground truth, links to each "
      "report). A drive that finished before with the same arguments and config, camera and "
      "model files is skipped, so an interrupted batch resumes; a failing drive does not stop "
      "the others (exit 1 at the end, the failures listed). With --slurm: a Slurm job array "
      "instead, one task per drive.");
  command->add_option("--manifest", arguments->manifest,
                      "YAML manifest: drives: a list of {name, one of kitti/images/video, and "
                      "run's other options as keys: camera, config, model, labels, "
                      "no_segmentation, scale, detector, h0, frames, sequential}; relative paths "
                      "are relative to the manifest; unknown keys are errors");
  command->add_option("--kitti-root", arguments->kitti_root,
                      "Instead of a manifest: the KITTI odometry folder (holding sequences/ and "
                      "poses/); one drive per --sequences entry, named after it");
  command->add_option("--sequences", arguments->sequences,
                      "With --kitti-root: sequences such as 00-10 or 00,02,05-07");
  command->add_option("--out", arguments->out, "The batch's output folder");
  command->add_option("--jobs", arguments->jobs, "Drives run at the same time")
      ->capture_default_str();
  command->add_option("--only-index", arguments->only_index,
                      "Run only the manifest's drive with this index (from 0), without the "
                      "summary: what each Slurm array task runs");
  command->add_option("--summarize", arguments->summarize,
                      "Only (re)write DIR/summary.* from the drives finished in DIR");
  command->add_flag("--slurm", arguments->slurm,
                    "Write OUT/slurm/drives.sbatch (a job array, one task per drive, each "
                    "`roadscale batch ... --only-index $SLURM_ARRAY_TASK_ID`), summary.sbatch "
                    "(--summarize OUT, after every task has ended) and submit.sh, instead of "
                    "running. OUT must be on a filesystem every node sees");
  command->add_flag("--submit", arguments->submit, "With --slurm: also run submit.sh (sbatch)");
  command->add_option("--partition", arguments->partition,
                      "With --slurm: the partition (default: the cluster's)");
  command->add_option("--time", arguments->time,
                      "With --slurm: each task's time limit, as sbatch --time (default: the "
                      "partition's)");
  command
      ->add_option("--cpus-per-task", arguments->cpus_per_task,
                   "With --slurm: CPUs per drive's task")
      ->capture_default_str();
  command->add_option("--sbatch-option", arguments->sbatch_options,
                      "With --slurm: another #SBATCH option for both jobs, e.g. "
                      "--sbatch-option=--account=lab (repeatable)");
  command->callback([arguments] { RunBatch(*arguments); });
}

}  // namespace roadscale::cli
