#include "roadscale/batch/summary_files.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

using Json = nlohmann::ordered_json;

std::string Rounded(const std::optional<double>& value, int decimals) {
  if (!value) return "–";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, *value);
  return text;
}

// The shortest text that reads back as the same double (nlohmann's, as metrics.json's); a
// count (no decimals) as an integer.
std::string Exact(const std::optional<double>& value, int decimals) {
  if (!value) return std::string();
  return decimals == 0 ? std::to_string(std::llround(*value)) : Json(*value).dump();
}

std::string HtmlEscape(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

// Text of a Markdown document as it reads: error reasons come from files anyone can edit, and
// raw HTML, a link or a table's '|' in them would render (issue 30). Only those characters are
// escaped, so that the file stays readable as text.
std::string MarkdownEscape(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (static_cast<unsigned char>(c) < 0x20) {
      escaped += ' ';
    } else if (std::string("\\`[]<>&|").find(c) != std::string::npos) {
      escaped += std::string("\\") + c;
    } else {
      escaped += c;
    }
  }
  return escaped;
}

std::string MeanNote(const BatchSummary& summary) {
  return summary.mean
             ? "mean over the " + std::to_string(summary.mean_over) + " drive(s) with ground truth"
             : "no drive has ground truth: no mean";
}

Json RowJson(const DriveRow& row) {
  Json json;
  json["name"] = row.name;
  if (!row.report.empty()) json["report"] = row.report;
  json["ground_truth"] = row.ground_truth;
  for (const SummaryColumn& column : SummaryColumns()) {
    const std::optional<double>& value = row.*column.value;
    json[column.key] = value ? Json(*value) : Json(nullptr);
  }
  return json;
}

void WriteText(const std::string& path, const std::string& text) {
  WriteFileAtomically(path, text);
}

}  // namespace

std::string FormatSummaryMarkdown(const BatchSummary& summary) {
  std::string text = "# Batch summary\n\n| drive |";
  std::string rule = "|---|";
  for (const SummaryColumn& column : SummaryColumns()) {
    text += std::string(" ") + column.header + " |";
    rule += "---:|";
  }
  text += "\n" + rule + "\n";
  const auto add_row = [&text](const DriveRow& row, const std::string& label) {
    text += "| " + label + " |";
    for (const SummaryColumn& column : SummaryColumns()) {
      text += " " + Rounded(row.*column.value, column.decimals) + " |";
    }
    text += "\n";
  };
  for (const DriveRow& row : summary.rows) {
    // Drive names are folder names of letters, digits and ._- (CheckDriveName): no escape.
    add_row(row, "[" + row.name + "](" + row.report + ")");
  }
  if (summary.mean) add_row(*summary.mean, "**mean**");
  text += "\n" + MeanNote(summary) +
          ". t_err and r_err: the KITTI devkit's metric over 100-800 m segments; scaled, held, "
          "unscaled: shares of frames; frames/s: frames over the drive's wall time.\n";
  for (const UnfinishedDrive& drive : summary.unfinished) {
    text += "\n- " + drive.name + ": " + MarkdownEscape(drive.reason);
  }
  if (!summary.unfinished.empty()) text += "\n";
  return text;
}

std::string FormatSummaryCsv(const BatchSummary& summary) {
  std::string text = "name";
  for (const SummaryColumn& column : SummaryColumns()) text += std::string(",") + column.key;
  text += "\n";
  const auto add_row = [&text](const DriveRow& row) {
    text += row.name;
    for (const SummaryColumn& column : SummaryColumns()) {
      text += "," + Exact(row.*column.value, column.decimals);
    }
    text += "\n";
  };
  for (const DriveRow& row : summary.rows) add_row(row);
  if (summary.mean) add_row(*summary.mean);
  return text;
}

std::string FormatSummaryJson(const BatchSummary& summary) {
  Json json;
  json["columns"] = Json::array();
  for (const SummaryColumn& column : SummaryColumns()) json["columns"].push_back(column.key);
  json["drives"] = Json::array();
  for (const DriveRow& row : summary.rows) json["drives"].push_back(RowJson(row));
  json["mean"] = summary.mean ? RowJson(*summary.mean) : Json(nullptr);
  json["mean_over"] = summary.mean_over;
  json["unfinished"] = Json::array();
  for (const UnfinishedDrive& drive : summary.unfinished) {
    json["unfinished"].push_back({{"name", drive.name}, {"reason", drive.reason}});
  }
  return json.dump(2) + "\n";
}

std::string FormatSummaryHtml(const BatchSummary& summary) {
  std::string text =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>roadscale batch "
      "summary</title>\n<style>body{font-family:sans-serif;margin:2em}"
      "table{border-collapse:collapse}th,td{padding:4px 10px;border-bottom:1px solid #ccc}"
      "td{text-align:right}td:first-child{text-align:left}tr.mean td{font-weight:bold;"
      "border-top:2px solid #333}</style></head>\n<body>\n<h1>Batch summary</h1>\n<table>\n"
      "<tr><th>drive</th>";
  for (const SummaryColumn& column : SummaryColumns()) {
    text += "<th>" + HtmlEscape(column.header) + "</th>";
  }
  text += "</tr>\n";
  const auto add_row = [&text](const DriveRow& row, const std::string& label,
                               const std::string& css_class) {
    text += "<tr" + (css_class.empty() ? std::string() : " class=\"" + css_class + "\"") + "><td>" +
            label + "</td>";
    for (const SummaryColumn& column : SummaryColumns()) {
      text += "<td>" + Rounded(row.*column.value, column.decimals) + "</td>";
    }
    text += "</tr>\n";
  };
  for (const DriveRow& row : summary.rows) {
    add_row(row, "<a href=\"" + HtmlEscape(row.report) + "\">" + HtmlEscape(row.name) + "</a>", "");
  }
  if (summary.mean) add_row(*summary.mean, "mean", "mean");
  text += "</table>\n<p>" + HtmlEscape(MeanNote(summary)) +
          ". t_err and r_err: the KITTI devkit's metric over 100-800 m segments; scaled, held, "
          "unscaled: shares of frames; frames/s: frames over the drive's wall time.</p>\n";
  if (!summary.unfinished.empty()) {
    text += "<p>Drives without results:</p>\n<ul>\n";
    for (const UnfinishedDrive& drive : summary.unfinished) {
      text += "<li>" + HtmlEscape(drive.name) + ": " + HtmlEscape(drive.reason) + "</li>\n";
    }
    text += "</ul>\n";
  }
  return text + "</body></html>\n";
}

std::vector<std::string> WriteSummaryFiles(const std::string& dir, const BatchSummary& summary) {
  const std::filesystem::path folder(dir);
  const std::vector<std::pair<std::string, std::string>> files = {
      {(folder / "summary.md").string(), FormatSummaryMarkdown(summary)},
      {(folder / "summary.csv").string(), FormatSummaryCsv(summary)},
      {(folder / "summary.json").string(), FormatSummaryJson(summary)},
      {(folder / "summary.html").string(), FormatSummaryHtml(summary)}};
  std::vector<std::string> paths;
  for (const auto& [path, text] : files) {
    WriteText(path, text);
    paths.push_back(path);
  }
  return paths;
}

}  // namespace roadscale::batch
