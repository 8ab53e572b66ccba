#include "roadscale/util/error.h"

namespace roadscale {

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
