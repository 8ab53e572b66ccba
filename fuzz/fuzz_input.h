#pragma once

// Helpers shared by the libFuzzer targets (fuzz/*_fuzzer.cc). Each target feeds one parser
// the fuzzer's bytes. roadscale::Error is the parsers' documented answer to bad input and is
// caught; anything else escaping (another exception type, a crash, a sanitizer report, a
// hang) is a defect: the command would end in "internal error" or worse.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace roadscale::fuzz {

// A folder of this process's own under the temporary directory ($TMPDIR: scripts/fuzz.sh
// points it to memory, /dev/shm, since rewriting a file on disk waits for the disk every
// time), for the readers that take a path; created once.
inline const std::filesystem::path& WorkDir() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("roadscale_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return dir;
}

// Writes the input to WorkDir()/name and returns its path.
inline std::string WriteInput(const uint8_t* data, size_t size, const std::string& name) {
  const std::string path = (WorkDir() / name).string();
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

inline std::string Text(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace roadscale::fuzz
