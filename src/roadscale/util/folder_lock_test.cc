#include "roadscale/util/folder_lock.h"

#include <csignal>
#include <filesystem>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "roadscale/testing/error_of.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using testing::ErrorOf;
using testing::ReadFileBytes;
using testing::TempDir;
using testing::WriteTextFile;

std::string LockPath(const TempDir& dir) { return dir.File(kFolderLockFile); }

std::string HostName() {
  char name[256] = {};
  gethostname(name, sizeof(name) - 1);
  return name;
}

TEST(FolderLock, HoldsThePidAndIsGoneWhenReleased) {
  TempDir dir;
  {
    const FolderLock lock(dir.path().string(), "run");
    const std::string holder = ReadFileBytes(LockPath(dir));
    EXPECT_EQ(holder.rfind(std::to_string(getpid()) + " ", 0), 0u) << holder;
    EXPECT_NE(holder.find(" run\n"), std::string::npos) << holder;
  }
  EXPECT_FALSE(std::filesystem::exists(LockPath(dir)));
  EXPECT_NO_THROW(FolderLock(dir.path().string(), "run"));
}

// Two batches into one folder both wrote frames.csv and batch.json (issue 30, defect 1).
TEST(FolderLock, ASecondHolderIsRefusedNamingTheFirst) {
  TempDir dir;
  const FolderLock first(dir.path().string(), "batch");
  const std::string message = ErrorOf([&] { FolderLock second(dir.path().string(), "run"); });
  EXPECT_EQ(message, dir.path().string() + ": output folder in use by process " +
                         std::to_string(getpid()) + " on " + HostName() +
                         " (roadscale batch); wait for it to end or choose another folder (lock "
                         "file " +
                         LockPath(dir) + ")");
  // The refused process leaves the holder's lock as it was.
  EXPECT_NE(ReadFileBytes(LockPath(dir)).find(" batch\n"), std::string::npos);
}

// A holder killed with -9 leaves its file behind; the kernel has dropped its flock.
TEST(FolderLock, AStaleLockOfAProcessThatIsGoneIsTakenOver) {
  TempDir dir;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const FolderLock lock(dir.path().string(), "run");
    pause();  // killed by the parent
    _exit(0);
  }
  for (int i = 0; i < 500 && ReadFileBytes(LockPath(dir)).empty(); ++i) usleep(10000);
  EXPECT_NE(ErrorOf([&] {
              FolderLock lock(dir.path().string(), "run");
            }).find("in use by process " + std::to_string(child) + " on "),
            std::string::npos);
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  ASSERT_TRUE(std::filesystem::exists(LockPath(dir)));  // stale: its holder is gone
  const FolderLock lock(dir.path().string(), "rescale");
  EXPECT_EQ(ReadFileBytes(LockPath(dir)).rfind(std::to_string(getpid()) + " ", 0), 0u);
}

TEST(FolderLock, AFileWrittenByHandWithoutAHolderIsNoLock) {
  TempDir dir;
  WriteTextFile(LockPath(dir), "garbage\n");
  EXPECT_NO_THROW(FolderLock(dir.path().string(), "run"));
}

TEST(FolderLock, AFolderThatCannotHoldTheLockIsNamed) {
  TempDir dir;
  EXPECT_EQ(ErrorOf([&] {
              FolderLock lock(dir.File("missing"), "run");
            }).rfind(dir.File("missing") + "/" + kFolderLockFile + ": cannot create", 0),
            0u);
}

}  // namespace
}  // namespace roadscale
