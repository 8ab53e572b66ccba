#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace roadscale {

// `text` without the spaces, tabs and line ends around it.
std::string Trim(std::string_view text);

// Strips a '#' comment and surrounding white space; true when nothing is left.
bool IsBlankOrComment(std::string_view line);

// Calls `visit(line, line_number)` for each line of `text` (without its '\n'; numbers from
// 1), after skipping a UTF-8 byte order mark at its start (some editors on Windows write one;
// it would otherwise be part of the first line's first token).
void ForEachLine(std::string_view text,
                 const std::function<void(std::string_view line, int line_number)>& visit);

// Parses every white-space separated number of `text`. Throws Error naming `path` and
// `line_number` on anything that is not a finite number.
std::vector<double> ParseNumbers(std::string_view text, const std::string& path, int line_number);

}  // namespace roadscale
