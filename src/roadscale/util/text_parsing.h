#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace roadscale {

// Strips a '#' comment and surrounding white space; true when nothing is left.
bool IsBlankOrComment(std::string_view line);

// Parses every white-space separated number of `text`. Throws Error naming `path` and
// `line_number` on anything that is not a finite number.
std::vector<double> ParseNumbers(std::string_view text, const std::string& path, int line_number);

}  // namespace roadscale
