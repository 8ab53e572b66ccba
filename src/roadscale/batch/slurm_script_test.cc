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

TEST(SlurmScriptTest, OutputFolderWithSpacesIsRefused) {
  SlurmOptions options;
  options.out = "/shared/my out";
  options.drives = 1;
  EXPECT_THROW(MakeSlurmScripts(options), Error);
}

}  // namespace
}  // namespace roadscale::batch
