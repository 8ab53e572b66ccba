#include "roadscale/util/atomic_file.h"

#include <csignal>
#include <filesystem>
#include <string>

#include <sys/resource.h>
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

size_t FilesIn(const TempDir& dir) {
  size_t count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    ++count;
  }
  return count;
}

TEST(AtomicFile, WritesAndReplacesTheWholeFile) {
  TempDir dir;
  WriteFileAtomically(dir.File("a.txt"), "first\n");
  EXPECT_EQ(ReadFileBytes(dir.File("a.txt")), "first\n");
  WriteFileAtomically(dir.File("a.txt"), "second, longer\n");
  EXPECT_EQ(ReadFileBytes(dir.File("a.txt")), "second, longer\n");
  EXPECT_EQ(FilesIn(dir), 1u);
}

// A full disk cut gt_poses_kitti.txt mid-row and left metrics.json empty (issue 30, defect 10):
// the file size limit makes every write past 1 KiB fail, as a full disk does.
TEST(AtomicFile, AFailedWriteLeavesThePreviousFileWholeAndNoTemporaryFile) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("metrics.json"), "{\"previous\": true}\n");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{1024, 1024};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      WriteFileAtomically(path, std::string(100000, 'x'));
    } catch (const Error& e) {
      _exit(std::string(e.what()).rfind(path + ": write failed (", 0) == 0 ? 3 : 4);
    }
    _exit(5);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3) << "3: the error named the file; 5: no error";
  EXPECT_EQ(ReadFileBytes(path), "{\"previous\": true}\n");
  EXPECT_EQ(FilesIn(dir), 1u);
}

TEST(AtomicFile, AMissingFolderIsNamed) {
  TempDir dir;
  EXPECT_EQ(ErrorOf([&] { WriteFileAtomically(dir.File("no/a.txt"), "x"); }),
            dir.File("no/a.txt") + ": cannot write: no such file or directory");
}

}  // namespace
}  // namespace roadscale
