#pragma once

#include <string>

namespace roadscale {

// Every file a user names (camera and config YAML, calib.txt, times.txt, trajectories, models)
// is opened through these two functions, so that a wrong path always ends in one line naming
// the file and the reason: "PATH: cannot open WHAT: is a directory" (or "no such file",
// "permission denied", "too many levels of symbolic links", ...).

// Throws Error unless `path` names something that can be opened for reading as a file
// (not a directory). For files a library opens itself (images, networks, videos), whose own
// failure says only "cannot decode".
void CheckInputFile(const std::string& path, const std::string& what);

// The whole file, read once (so that a pipe such as /dev/stdin works). Throws Error as
// CheckInputFile does, on a read error, and beyond kMaxInputFileBytes (a device such as
// /dev/zero never ends).
std::string ReadInputFile(const std::string& path, const std::string& what);

inline constexpr size_t kMaxInputFileBytes = size_t{256} << 20;

}  // namespace roadscale
