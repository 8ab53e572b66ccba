#include "roadscale/batch/slurm_script.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

namespace fs = std::filesystem;

std::string SlurmFolder(const std::string& out) { return (fs::path(out) / "slurm").string(); }

// The #SBATCH lines both jobs share.
std::string CommonOptions(const SlurmOptions& options) {
  std::string text;
  if (!options.partition.empty()) text += "#SBATCH --partition=" + options.partition + "\n";
  for (const std::string& option : options.sbatch_options) text += "#SBATCH " + option + "\n";
  return text;
}

}  // namespace

std::string ShellQuote(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           std::string("_./:=@%+,-").find(c) != std::string::npos;
  });
  if (plain) return text;
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

SlurmScripts MakeSlurmScripts(const SlurmOptions& options) {
  // #SBATCH lines are not parsed by a shell: a path there cannot be quoted.
  if (options.out.find_first_of(" \t\n") != std::string::npos) {
    throw Error("--out '" + options.out + "': Slurm scripts need a batch folder without spaces");
  }
  if (options.drives == 0) throw Error("a batch without drives has no Slurm job array");
  const std::string slurm = SlurmFolder(options.out);
  std::string input;
  for (const std::string& word : options.batch_input) input += " " + ShellQuote(word);

  const std::string roadscale = ShellQuote(options.roadscale);
  const std::string out = ShellQuote(options.out);
  SlurmScripts scripts;
  scripts.drives =
      "#!/bin/bash\n"
      "# Written by `roadscale batch --slurm`: one array task per drive of the batch; each runs\n"
      "# that drive as `roadscale run` would, into " +
      options.out +
      "/<name>/ (skipped when it\n"
      "# finished before with the same config). Submit with submit.sh.\n"
      "#SBATCH --job-name=roadscale-drives\n"
      "#SBATCH --array=0-" +
      std::to_string(options.drives - 1) + "\n" +
      "#SBATCH --cpus-per-task=" + std::to_string(options.cpus_per_task) + "\n" +
      (options.time.empty() ? "" : "#SBATCH --time=" + options.time + "\n") +
      "#SBATCH --output=" + slurm + "/drive_%a.out\n" + CommonOptions(options) + "exec " +
      roadscale + " batch" + input + " --out " + out + " --only-index \"$SLURM_ARRAY_TASK_ID\"\n";
  scripts.summary =
      "#!/bin/bash\n"
      "# Written by `roadscale batch --slurm`: the batch summary (" +
      options.out +
      "/summary.*),\n"
      "# once every drive's task has ended.\n"
      "#SBATCH --job-name=roadscale-summary\n"
      "#SBATCH --cpus-per-task=1\n"
      "#SBATCH --output=" +
      slurm + "/summary.out\n" + CommonOptions(options) + "exec " + roadscale +
      " batch --summarize " + out + "\n";
  scripts.submit =
      "#!/bin/bash\n"
      "# Written by `roadscale batch --slurm`: submits the drives' job array, then the summary\n"
      "# to run after every task has ended (afterany: it lists failed drives too).\n"
      "set -euo pipefail\n"
      "drives_job=$(sbatch --parsable " +
      ShellQuote(slurm + "/drives.sbatch") + ")\n" +
      "drives_job=${drives_job%%;*}  # \"id;cluster\" on a federation\n"
      "summary_job=$(sbatch --parsable --dependency=afterany:\"$drives_job\" " +
      ShellQuote(slurm + "/summary.sbatch") + ")\n" + "echo \"drives: job $drives_job (" +
      std::to_string(options.drives) + " array tasks); summary: job ${summary_job%%;*}\"\n";
  return scripts;
}

std::string WriteSlurmScripts(const SlurmOptions& options) {
  const std::string slurm = SlurmFolder(options.out);
  std::error_code error;
  fs::create_directories(slurm, error);
  if (error || !fs::is_directory(slurm)) {
    ThrowFileError(slurm, "cannot create the folder of the Slurm scripts" +
                              (error ? " (" + error.message() + ")" : std::string()));
  }
  const SlurmScripts scripts = MakeSlurmScripts(options);
  for (const auto& [name, text] :
       {std::pair{"drives.sbatch", &scripts.drives}, std::pair{"summary.sbatch", &scripts.summary},
        std::pair{"submit.sh", &scripts.submit}}) {
    const std::string path = slurm + "/" + name;
    std::ofstream file(path);
    file << *text;
    if (!file.flush()) ThrowFileError(path, "cannot write the Slurm script");
  }
  const std::string submit = slurm + "/submit.sh";
  fs::permissions(submit, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add, error);
  if (error) ThrowFileError(submit, "cannot make it executable (" + error.message() + ")");
  return submit;
}

}  // namespace roadscale::batch
