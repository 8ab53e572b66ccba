#include "roadscale/util/input_file.h"

#include <filesystem>

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using testing::TempDir;
using testing::WriteTextFile;

std::string OpenErrorOf(const std::string& path) {
  try {
    ReadInputFile(path, "camera YAML file");
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(InputFile, ReadsTheWholeFile) {
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("a.txt"), "one\ntwo\n");
  EXPECT_EQ(ReadInputFile(path, "file"), "one\ntwo\n");
  EXPECT_NO_THROW(CheckInputFile(path, "file"));
}

TEST(InputFile, ADirectoryIsNamedAsSuch) {
  TempDir dir;
  EXPECT_EQ(OpenErrorOf(dir.path().string()),
            dir.path().string() + ": cannot open camera YAML file: is a directory");
  EXPECT_THROW(CheckInputFile(dir.path().string(), "image"), Error);
}

TEST(InputFile, MissingFileAndEmptyPath) {
  TempDir dir;
  EXPECT_EQ(OpenErrorOf(dir.File("absent.yaml")),
            dir.File("absent.yaml") + ": cannot open camera YAML file: no such file");
  EXPECT_EQ(OpenErrorOf(""), "'': cannot open camera YAML file: the path is empty");
}

TEST(InputFile, SymlinkLoop) {
  TempDir dir;
  std::filesystem::create_symlink(dir.File("b"), dir.File("a"));
  std::filesystem::create_symlink(dir.File("a"), dir.File("b"));
  EXPECT_EQ(OpenErrorOf(dir.File("a")),
            dir.File("a") + ": cannot open camera YAML file: too many levels of symbolic links");
}

TEST(InputFile, PermissionDenied) {
  if (geteuid() == 0) GTEST_SKIP() << "root reads every file";
  TempDir dir;
  const std::string path = WriteTextFile(dir.File("secret.yaml"), "Camera: {}\n");
  ASSERT_EQ(chmod(path.c_str(), 0), 0);
  EXPECT_EQ(OpenErrorOf(path), path + ": cannot open camera YAML file: permission denied");
}

}  // namespace
}  // namespace roadscale
