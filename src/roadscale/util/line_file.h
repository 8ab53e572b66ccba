#pragma once

#include <fstream>
#include <string>

namespace roadscale {

// Appends `line` and '\n' to `file` (open on `path`) and flushes, so that the row is on disk
// whatever stops the run next. When the write fails (disk full, file size limit) the file is
// closed and cut back to its length before the line, so that it holds whole rows only, and
// Error names `path`.
void WriteWholeLine(std::ofstream& file, const std::string& path, const std::string& line);

}  // namespace roadscale
