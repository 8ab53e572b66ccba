// A batch folder's batch.json as --summarize reads it (DriveNamesIn, then the summary of those
// drives in every format): batch.json is a file anyone can edit (issue 30).
#include <filesystem>

#include "roadscale/batch/batch_folder.h"
#include "roadscale/batch/summary_files.h"
#include "roadscale/batch/summary_table.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool prepared = [] {
    std::filesystem::create_directories(roadscale::fuzz::WorkDir() / "batch");
    return true;
  }();
  (void)prepared;
  roadscale::fuzz::WriteInput(data, size, "batch/batch.json");
  const std::string dir = (roadscale::fuzz::WorkDir() / "batch").string();
  try {
    const roadscale::batch::BatchSummary summary =
        roadscale::batch::SummarizeDrives(dir, roadscale::batch::DriveNamesIn(dir));
    roadscale::batch::FormatSummaryMarkdown(summary);
    roadscale::batch::FormatSummaryCsv(summary);
    roadscale::batch::FormatSummaryJson(summary);
    roadscale::batch::FormatSummaryHtml(summary);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
