#include "roadscale/util/folder_lock.h"

#include <cerrno>
#include <filesystem>
#include <string>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::string ErrnoText() { return ErrnoReason(errno); }

std::string HostName() {
  char name[256] = {};
  if (gethostname(name, sizeof(name) - 1) != 0) return "unknown";
  return name;
}

// The holder's line ("1234 node7 batch"), for the message that the folder is in use.
std::string HolderOf(int fd) {
  char text[512] = {};
  const ssize_t size = pread(fd, text, sizeof(text) - 1, 0);
  std::string holder = size > 0 ? std::string(text, static_cast<size_t>(size)) : std::string();
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
  for (char& c : holder) {
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';  // one line, whatever the file holds
  }
  return holder;
}

// "process 1234 on node7 (roadscale batch)" from the holder's line.
std::string Describe(const std::string& holder) {
  const size_t first = holder.find(' ');
  const size_t second = first == std::string::npos ? first : holder.find(' ', first + 1);
  if (second == std::string::npos) return "another process";
  return "process " + holder.substr(0, first) + " on " +
         holder.substr(first + 1, second - first - 1) + " (roadscale " + holder.substr(second + 1) +
         ")";
}

bool SameFile(int fd, const std::string& path) {
  struct stat open_file {};
  struct stat named_file {};
  return fstat(fd, &open_file) == 0 && stat(path.c_str(), &named_file) == 0 &&
         open_file.st_dev == named_file.st_dev && open_file.st_ino == named_file.st_ino;
}

}  // namespace

FolderLock::FolderLock(const std::string& folder, const std::string& command)
    : path_((std::filesystem::path(folder) / kFolderLockFile).string()) {
  // A holder removes the file as it releases the lock; whoever opened that file just before
  // then holds a lock on a name that is gone, so the lock counts only while the name still
  // leads to the file locked.
  for (;;) {
    fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      ThrowFileError(path_, "cannot create the output folder's lock (" + ErrnoText() + ")");
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = HolderOf(fd_);
      close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK) {
        ThrowFileError(folder, "output folder in use by " + Describe(holder) +
                                   "; wait for it to end or choose another folder (lock file " +
                                   path_ + ")");
      }
      errno = error;
      ThrowFileError(path_, "cannot lock the output folder (" + ErrnoText() + ")");
    }
    if (SameFile(fd_, path_)) break;
    close(fd_);
  }
  // The lock is ours: a line left by a holder that died (kill -9, power loss) is replaced.
  const std::string holder = std::to_string(getpid()) + " " + HostName() + " " + command + "\n";
  if (ftruncate(fd_, 0) != 0 ||
      pwrite(fd_, holder.data(), holder.size(), 0) != static_cast<ssize_t>(holder.size())) {
    const std::string reason = ErrnoText();
    unlink(path_.c_str());
    close(fd_);
    fd_ = -1;
    ThrowFileError(path_, "cannot write the output folder's lock (" + reason + ")");
  }
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  unlink(path_.c_str());  // while still locked: see the constructor
  close(fd_);
}

FolderLock::FolderLock(FolderLock&& other) noexcept
    : path_(std::move(other.path_)), fd_(other.fd_) {
  other.fd_ = -1;
}

}  // namespace roadscale
