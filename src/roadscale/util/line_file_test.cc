#include "roadscale/util/line_file.h"

#include <csignal>

#include <sys/resource.h>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::string Contents(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST(LineFile, WritesWholeLines) {
  testing::TempDir dir;
  const std::string path = dir.File("rows.txt");
  std::ofstream file(path);
  WriteWholeLine(file, path, "1 2 3");
  WriteWholeLine(file, path, "4 5 6");
  EXPECT_EQ(Contents(path), "1 2 3\n4 5 6\n");
}

TEST(LineFile, AFullDiskLeavesOnlyWholeLines) {
  // A file size limit of 4 KiB stands in for a full disk; its signal is ignored so that the
  // write fails (EFBIG) instead of ending the test.
  testing::TempDir dir;
  const std::string path = dir.File("rows.txt");
  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit previous_limit;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &previous_limit), 0);
  rlimit limit = previous_limit;
  limit.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  std::ofstream file(path);
  const std::string row(99, 'x');  // 100 bytes a line: the 41st does not fit
  int written = 0;
  std::string message;
  try {
    for (; written < 100; ++written) WriteWholeLine(file, path, row);
  } catch (const Error& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &previous_limit);
  std::signal(SIGXFSZ, previous_handler);
  EXPECT_EQ(written, 40);
  EXPECT_EQ(message.rfind(path + ": write failed", 0), 0u) << message;
  const std::string contents = Contents(path);
  EXPECT_EQ(contents.size(), 4000u);
  EXPECT_EQ(contents.back(), '\n');
}

}  // namespace
}  // namespace roadscale
