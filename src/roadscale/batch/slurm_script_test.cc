#include "roadscale/batch/slurm_script.h"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

std::string Golden(const std::string& name) {
  std::ifstream file(std::string(ROADSCALE_BATCH_TESTDATA) + "/" + name);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The scripts for a three-drive manifest, as `roadscale batch --manifest /data/m.yaml --out
// /shared/out --slurm --partition gpu --time 2:00:00 --sbatch-option=--account=lab` writes
// them. Compared with files a person has read: any change to the scripts shows up in review.
TEST(SlurmScriptTest, ScriptsMatchTheGoldenFiles) {
  SlurmOptions options;
  options.roadscale = "/opt/roadscale/bin/roadscale";
  options.batch_input = {"--manifest", "/data/m.yaml"};
  options.out = "/shared/out";
  options.drives = 3;
  options.partition = "gpu";
  options.time = "2:00:00";
  options.sbatch_options = {"--account=lab"};
  const SlurmScripts scripts = MakeSlurmScripts(options);
  EXPECT_EQ(scripts.drives, Golden("drives.sbatch")) << scripts.drives;
  EXPECT_EQ(scripts.summary, Golden("summary.sbatch")) << scripts.summary;
  EXPECT_EQ(scripts.submit, Golden("submit.sh")) << scripts.submit;
}

TEST(SlurmScriptTest, QuotesShellWords) {
  EXPECT_EQ(ShellQuote("/data/m.yaml"), "/data/m.yaml");
  EXPECT_EQ(ShellQuote("a b"), "'a b'");
  EXPECT_EQ(ShellQuote(""), "''");
  EXPECT_EQ(ShellQuote("$HOME"), "'$HOME'");
  EXPECT_EQ(ShellQuote("it's"), "'it'\\''s'");
}

SlurmOptions GoodOptions() {
  SlurmOptions options;
  options.roadscale = "/opt/roadscale/bin/roadscale";
  options.batch_input = {"--manifest", "/data/m.yaml"};
  options.out = "/shared/out";
  options.drives = 2;
  return options;
}

// The message MakeSlurmScripts throws for `options`, which must be one line naming `option`.
std::string RefusalOf(const SlurmOptions& options, const std::string& option) {
  try {
    MakeSlurmScripts(options);
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(option + " '", 0), 0u) << message;
    return message;
  }
  ADD_FAILURE() << "accepted " << option;
  return "";
}

// A line end in any value would close its #SBATCH directive and run the rest as a command in
// every array task (issue 30, defect 2).
TEST(SlurmScriptTest, ValuesThatCouldLeaveTheirDirectiveAreRefused) {
  for (const std::string bad :
       {"lab\ntouch PWNED", "lab\rtouch PWNED", "--account=lab\n", "--account=lab touch",
        "--account=$(id)", "account=lab", "--comment=a;b", "-", "--x=\x1b[2J"}) {
    SlurmOptions options = GoodOptions();
    options.sbatch_options = {"--account=lab", bad};
    RefusalOf(options, "--sbatch-option");
  }
  for (const std::string bad : {"short\ntouch PWNED", "short debug", "gpu;id", "`id`", "gpu%a"}) {
    SlurmOptions options = GoodOptions();
    options.partition = bad;
    RefusalOf(options, "--partition");
  }
  for (const std::string bad : {"1:00:00\ntouch PWNED", "1:00:00 ", "an hour", "1:2:3:4", "-5"}) {
    SlurmOptions options = GoodOptions();
    options.time = bad;
    RefusalOf(options, "--time");
  }
  EXPECT_NE(RefusalOf(
                [] {
                  SlurmOptions options = GoodOptions();
                  options.sbatch_options = {"--account=lab\ntouch PWNED"};
                  return options;
                }(),
                "--sbatch-option")
                .find("lab\\ntouch PWNED"),
            std::string::npos);
}

TEST(SlurmScriptTest, UsualValuesAreAccepted) {
  SlurmOptions options = GoodOptions();
  options.partition = "gpu,short-2.x";
  options.sbatch_options = {"--account=lab",    "--gres=gpu:1", "--mail-user=me@lab.org",
                            "--mem-per-cpu=4G", "-q",           "--exclusive"};
  for (const std::string time :
       {"30", "30:00", "2:00:00", "1-0", "1-12:00", "7-00:00:00", "UNLIMITED", "infinite"}) {
    options.time = time;
    EXPECT_NO_THROW(MakeSlurmScripts(options)) << time;
  }
}

// sbatch expands '%' in --output= ("%a" is the task), and a backslash turns that off.
TEST(SlurmScriptTest, OutputFolderSbatchWouldRewriteIsRefused) {
  for (const std::string bad :
       {"/shared/100%a", "/shared/a\\b", "/shared/out\ntouch PWNED", "/shared/out\t"}) {
    SlurmOptions options = GoodOptions();
    options.out = bad;
    RefusalOf(options, "--out");
  }
}

TEST(SlurmScriptTest, OutputFolderWithSpacesIsRefused) {
  SlurmOptions options;
  options.out = "/shared/my out";
  options.drives = 1;
  EXPECT_THROW(MakeSlurmScripts(options), Error);
}

}  // namespace
}  // namespace roadscale::batch
