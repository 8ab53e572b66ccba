#include "roadscale/util/text_parsing.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

}  // namespace

std::string Trim(std::string_view text) {
  size_t begin = 0, end = text.size();
  while (begin < end && IsSpace(text[begin])) ++begin;
  while (end > begin && IsSpace(text[end - 1])) --end;
  return std::string(text.substr(begin, end - begin));
}

bool IsBlankOrComment(std::string_view line) {
  for (char c : line) {
    if (c == '#') return true;
    if (!IsSpace(c)) return false;
  }
  return true;
}

void ForEachLine(std::string_view text,
                 const std::function<void(std::string_view line, int line_number)>& visit) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) {
    text.remove_prefix(kByteOrderMark.size());
  }
  int line_number = 1;
  while (!text.empty()) {
    const size_t end = text.find('\n');
    visit(text.substr(0, end), line_number++);
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
}

std::vector<double> ParseNumbers(std::string_view text, const std::string& path, int line_number) {
  std::vector<double> numbers;
  size_t pos = 0;
  while (pos < text.size()) {
    while (pos < text.size() && IsSpace(text[pos])) ++pos;
    if (pos == text.size()) break;
    size_t end = pos;
    while (end < text.size() && !IsSpace(text[end])) ++end;
    const std::string token(text.substr(pos, end - pos));
    char* parsed_end = nullptr;
    errno = 0;
    const double value = std::strtod(token.c_str(), &parsed_end);
    if (parsed_end != token.c_str() + token.size() || errno == ERANGE || !std::isfinite(value)) {
      ThrowFileError(path, line_number, "expected a number, found '" + token + "'");
    }
    numbers.push_back(value);
    pos = end;
  }
  return numbers;
}

}  // namespace roadscale
