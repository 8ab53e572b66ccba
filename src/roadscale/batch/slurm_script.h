#pragma once

#include <string>
#include <vector>

namespace roadscale::batch {

// What the Slurm scripts of a batch need. Paths must be absolute: the tasks run on other
// nodes, in other folders.
struct SlurmOptions {
  std::string roadscale;                 // the roadscale binary
  std::vector<std::string> batch_input;  // "--manifest FILE" or "--kitti-root R --sequences S"
  std::string out;                       // the batch folder (on a filesystem every node sees)
  size_t drives = 0;
  std::string partition;                    // empty: the cluster's default
  std::string time;                         // per task, sbatch's --time; empty: the default
  int cpus_per_task = 2;                    // run's segmentation, frontend and scale threads
  std::vector<std::string> sbatch_options;  // more "#SBATCH" options, e.g. "--account=lab"
};

// Throws Error naming the option unless every value is safe on an #SBATCH line. sbatch reads
// those lines itself, without a shell, so nothing there can be quoted: a line end would close
// the directive and run the rest as a command in every task. Each option therefore gets a strict
// character set: --partition letters, digits and _.,-; --time sbatch's time formats only; each
// --sbatch-option one word "-..." of letters, digits and _./:=@+,-; --out no white space,
// control character, '%' or '\' (sbatch expands '%' in --output=, and a '\' turns the %a of
// the task logs off).
void CheckSlurmOptions(const SlurmOptions& options);

// The scripts written into DIR/slurm/:
struct SlurmScripts {
  // drives.sbatch: a job array with one task per drive, each running `roadscale batch
  // ... --only-index $SLURM_ARRAY_TASK_ID` (that drive alone, with the batch's resume);
  std::string drives;
  // summary.sbatch: `roadscale batch --summarize DIR`;
  std::string summary;
  // submit.sh: submits drives.sbatch, then summary.sbatch to start after every task has
  // ended (afterany: failed drives too, the summary lists them), and prints both job ids.
  std::string submit;
};
// Throws Error as CheckSlurmOptions does.
SlurmScripts MakeSlurmScripts(const SlurmOptions& options);

// Writes DIR/slurm/{drives.sbatch,summary.sbatch,submit.sh} (submit.sh executable); returns
// submit.sh's path. Throws Error naming what cannot be written.
std::string WriteSlurmScripts(const SlurmOptions& options);

// `text` as one word for a POSIX shell: as it is when it holds only letters, digits and
// _./:=@%+,- (readable scripts), else in single quotes.
std::string ShellQuote(const std::string& text);

}  // namespace roadscale::batch
