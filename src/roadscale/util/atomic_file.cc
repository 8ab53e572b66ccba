#include "roadscale/util/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <filesystem>

#include <fcntl.h>
#include <unistd.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

bool WriteAll(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& text) {
  const std::filesystem::path target(path);
  // Beside the target, so that the rename stays on one file system and is atomic.
  const std::string temporary =
      (target.parent_path() /
       ("." + target.filename().string() + ".tmp" + std::to_string(static_cast<long>(::getpid()))))
          .string();
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) ThrowFileError(path, std::string("cannot write: ") + ErrnoReason(errno));
  const bool written = WriteAll(fd, text) && ::fsync(fd) == 0;
  int saved_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (written && !closed) saved_errno = errno;
  if (!written || !closed) {
    std::remove(temporary.c_str());
    ThrowFileError(path, std::string("write failed (") + ErrnoReason(saved_errno) + ")");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    std::remove(temporary.c_str());
    ThrowFileError(path, std::string("cannot replace the file: ") + ErrnoReason(rename_errno));
  }
}

}  // namespace roadscale
