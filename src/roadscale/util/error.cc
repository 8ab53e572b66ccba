#include "roadscale/util/error.h"

#include <cctype>
#include <system_error>

namespace roadscale {

std::string ErrnoReason(int error_number) {
  std::string text = std::generic_category().message(error_number);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

void ThrowFileError(const std::string& path, int line, const std::string& message) {
  if (line > 0) throw Error(path + ":" + std::to_string(line) + ": " + message);
  throw Error(path + ": " + message);
}

void ThrowFileError(const std::string& path, const std::string& message) {
  ThrowFileError(path, 0, message);
}

void CheckOption(bool condition, const char* name, const std::string& message) {
  if (!condition) throw Error(std::string("invalid option ") + name + ": " + message);
}

}  // namespace roadscale
