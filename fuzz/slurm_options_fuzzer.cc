// --slurm's options (MakeSlurmScripts): the input's NUL-separated fields are --partition,
// --time, --out and --sbatch-option values. Besides crashes, it checks the property the option
// checks exist for (issue 30): whatever is accepted, every line of drives.sbatch and
// summary.sbatch is a comment, an #SBATCH directive or the one exec line, so that no value
// runs as a command in the array tasks.
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "roadscale/batch/slurm_script.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

namespace {

std::vector<std::string> Fields(const std::string& text) {
  std::vector<std::string> fields;
  std::string field;
  for (const char c : text) {
    if (c == '\0') {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

void CheckLines(const std::string& script) {
  std::istringstream lines(script);
  int execs = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("exec ", 0) == 0) {
      ++execs;
    } else if (line.empty() || line[0] != '#') {
      std::abort();  // a line a shell would run: an injected command
    }
  }
  if (execs != 1) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<std::string> fields = Fields(roadscale::fuzz::Text(data, size));
  roadscale::batch::SlurmOptions options;
  options.roadscale = "/opt/roadscale/bin/roadscale";
  options.batch_input = {"--manifest", "/data/m.yaml"};
  options.drives = 3;
  options.partition = fields.size() > 0 ? fields[0] : "";
  options.time = fields.size() > 1 ? fields[1] : "";
  options.out = fields.size() > 2 ? "/" + fields[2] : "/shared/out";
  for (size_t i = 3; i < fields.size(); ++i) options.sbatch_options.push_back(fields[i]);
  try {
    const roadscale::batch::SlurmScripts scripts = roadscale::batch::MakeSlurmScripts(options);
    CheckLines(scripts.drives);
    CheckLines(scripts.summary);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
