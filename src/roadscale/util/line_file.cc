#include "roadscale/util/line_file.h"

#include <filesystem>
#include <system_error>

#include "roadscale/util/error.h"

namespace roadscale {

void WriteWholeLine(std::ofstream& file, const std::string& path, const std::string& line) {
  const std::streampos end = file.tellp();
  file << line << '\n';
  file.flush();
  if (file) return;
  // Closing first: a later flush of what is left in the stream's buffer could add to the file
  // after it was cut.
  file.close();
  if (end != std::streampos(-1)) {
    std::error_code ignored;
    std::filesystem::resize_file(path, static_cast<std::uintmax_t>(end), ignored);
  }
  ThrowFileError(path, "write failed (disk full, or the file removed or too large)");
}

}  // namespace roadscale
