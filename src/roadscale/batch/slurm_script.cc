#include "roadscale/batch/slurm_script.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <regex>

#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

namespace fs = std::filesystem;

std::string SlurmFolder(const std::string& out) { return (fs::path(out) / "slurm").string(); }

// `text` on one line for an error message: control characters as C escapes ("\n", "\x1b").
std::string Shown(const std::string& text) {
  std::string shown;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      shown += "\\n";
    } else if (c == '\t') {
      shown += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02x", byte);
      shown += hex;
    } else {
      shown += c;
    }
  }
  return shown;
}

bool OnlyCharacters(const std::string& text, const std::string& punctuation) {
  return std::all_of(text.begin(), text.end(), [&](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           punctuation.find(c) != std::string::npos;
  });
}

[[noreturn]] void Refuse(const char* option, const std::string& value, const std::string& why) {
  throw Error(std::string(option) + " '" + Shown(value) + "': " + why);
}

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

void CheckSlurmOptions(const SlurmOptions& options) {
  const bool out_plain = std::none_of(options.out.begin(), options.out.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte <= 0x20 || byte == 0x7f || c == '%' || c == '\\';
  });
  if (!out_plain) {
    Refuse("--out", options.out,
           "Slurm scripts need a batch folder without spaces, control characters, '%' or '\\' "
           "(it goes unquoted into #SBATCH --output=, where sbatch expands '%')");
  }
  if (!options.partition.empty() && !OnlyCharacters(options.partition, "_.,-")) {
    Refuse("--partition", options.partition,
           "expected partition names of letters, digits and _.- (several separated by commas)");
  }
  // sbatch's formats: M, M:S, H:M:S, D-H, D-H:M, D-H:M:S, or no limit.
  static const std::regex time_format(R"(([0-9]+-)?[0-9]+(:[0-9]+){0,2}|(?:unlimited|infinite))",
                                      std::regex::icase);
  if (!options.time.empty() && !std::regex_match(options.time, time_format)) {
    Refuse("--time", options.time,
           "expected sbatch's time format: minutes, M:S, H:M:S, D-H, D-H:M, D-H:M:S or UNLIMITED");
  }
  for (const std::string& option : options.sbatch_options) {
    if (option.size() < 2 || option[0] != '-' || !OnlyCharacters(option, "_./:=@+,-")) {
      Refuse("--sbatch-option", option,
             "expected one sbatch option such as --account=lab: a word starting with '-' of "
             "letters, digits and _./:=@+,-");
    }
  }
}

SlurmScripts MakeSlurmScripts(const SlurmOptions& options) {
  CheckSlurmOptions(options);
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
    WriteFileAtomically(slurm + "/" + name, *text);
  }
  const std::string submit = slurm + "/submit.sh";
  fs::permissions(submit, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add, error);
  if (error) ThrowFileError(submit, "cannot make it executable (" + error.message() + ")");
  return submit;
}

}  // namespace roadscale::batch
