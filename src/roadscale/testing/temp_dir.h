#pragma once

#include <filesystem>
#include <string>

namespace roadscale::testing {

// A fresh folder under the system's temporary directory, removed with its contents when
// the object goes out of scope.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string File(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// Writes `contents` to `path` (creating parent folders) and returns the path.
std::string WriteTextFile(const std::string& path, const std::string& contents);

// The whole of the file at `path`, byte for byte ("" when it cannot be read).
std::string ReadFileBytes(const std::string& path);

}  // namespace roadscale::testing
