#pragma once

#include <string>

namespace roadscale {

// An advisory lock on an output folder, so that two processes never write the same files
// (two batches into one folder lost rows of frames.csv and overwrote batch.json; issue 30).
// The lock is FOLDER/.roadscale.lock, holding the holder's pid, host and command, and an
// flock() on it: the kernel drops that when the holder ends in any way (kill -9 included), so
// a lock file left by a process that is gone is stale by construction and simply taken over.
// The file is removed when the lock is released.
inline constexpr char kFolderLockFile[] = ".roadscale.lock";

class FolderLock {
 public:
  // Locks `folder` (which must exist) for `command` ("run", "batch", ...). Throws Error naming
  // the folder, the holder's pid, host and command when another process holds it, or naming the
  // lock file when it cannot be created or locked.
  FolderLock(const std::string& folder, const std::string& command);
  ~FolderLock();
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&&) = delete;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace roadscale
