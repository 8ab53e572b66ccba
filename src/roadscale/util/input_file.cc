#include "roadscale/util/input_file.h"

#include <cerrno>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void ThrowCannotOpen(const std::string& path, const std::string& what,
                                  const std::string& reason) {
  ThrowFileError(path, "cannot open " + what + ": " + reason);
}

// A file descriptor closed on every path out of ReadInputFile.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Opens `path` read-only, throwing the reason it cannot be.
int OpenOrThrow(const std::string& path, const std::string& what) {
  if (path.empty()) ThrowCannotOpen("''", what, "the path is empty");
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found) ThrowCannotOpen(path, what, "no such file");
  if (error) ThrowCannotOpen(path, what, ErrnoReason(error.value()));
  if (status.type() == fs::file_type::directory) ThrowCannotOpen(path, what, "is a directory");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) ThrowCannotOpen(path, what, ErrnoReason(errno));
  return fd;
}

}  // namespace

void CheckInputFile(const std::string& path, const std::string& what) {
  const Descriptor fd(OpenOrThrow(path, what));
}

std::string ReadInputFile(const std::string& path, const std::string& what) {
  const Descriptor fd(OpenOrThrow(path, what));
  std::string contents;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t count = ::read(fd.get(), buffer, sizeof(buffer));
    if (count == 0) break;
    if (count < 0) {
      if (errno == EINTR) continue;
      ThrowFileError(path, "cannot read " + what + ": " + ErrnoReason(errno));
    }
    contents.append(buffer, static_cast<size_t>(count));
    if (contents.size() > kMaxInputFileBytes) {
      ThrowFileError(path, "cannot read " + what + ": larger than " +
                               std::to_string(kMaxInputFileBytes >> 20) + " MiB");
    }
  }
  return contents;
}

}  // namespace roadscale
