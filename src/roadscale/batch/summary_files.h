#pragma once

#include <string>
#include <vector>

#include "roadscale/batch/summary_table.h"

namespace roadscale::batch {

// The batch summary in four forms, laid out like the paper's per-sequence tables: one row per
// drive, then the mean over the drives with ground truth, then the drives without a row.

// Markdown: a table with each drive's name linked to its report.
std::string FormatSummaryMarkdown(const BatchSummary& summary);

// CSV: `name`, then SummaryColumns' keys; a value's text is the shortest that reads back as
// the same double (the drive's metrics.json writes them the same way, so the numbers match
// digit for digit); an unset value is empty. The mean's row is named "mean". Unfinished
// drives have no row.
std::string FormatSummaryCsv(const BatchSummary& summary);

// JSON: {"columns": [...], "drives": [{"name", "report", "ground_truth", <key>: value|null,
// ...}], "mean": {...}|null, "mean_over": N, "unfinished": [{"name", "reason"}]}.
std::string FormatSummaryJson(const BatchSummary& summary);

// One self-contained HTML page with the table, each name a link to the drive's report.
std::string FormatSummaryHtml(const BatchSummary& summary);

// Writes DIR/summary.md, summary.csv, summary.json and summary.html; returns their paths.
// Throws Error naming a file that cannot be written.
std::vector<std::string> WriteSummaryFiles(const std::string& dir, const BatchSummary& summary);

}  // namespace roadscale::batch
