#include "roadscale/batch/batch_folder.h"

#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/batch/drive_record.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

using roadscale::testing::TempDir;
using ::testing::ElementsAre;

void WriteRecordOf(const TempDir& batch, const std::string& name) {
  std::filesystem::create_directories(batch.path() / name);
  DriveRecord record;
  record.name = name;
  WriteDriveRecord(DriveFolder(batch.path().string(), name), record);
}

TEST(BatchFolderTest, DriveListKeepsTheManifestsOrder) {
  TempDir batch;
  WriteDriveList(batch.path().string(), {"10", "02", "x"});
  EXPECT_THAT(DriveNamesIn(batch.path().string()), ElementsAre("10", "02", "x"));
}

TEST(BatchFolderTest, WithoutAListTheFoldersWithARecordInNameOrder) {
  TempDir batch;
  WriteRecordOf(batch, "b");
  WriteRecordOf(batch, "a");
  std::filesystem::create_directories(batch.path() / "slurm");  // no record: not a drive
  EXPECT_THAT(DriveNamesIn(batch.path().string()), ElementsAre("a", "b"));
}

TEST(BatchFolderTest, MissingFolderIsAnError) {
  TempDir batch;
  EXPECT_THROW(DriveNamesIn(batch.File("nowhere")), Error);
}

}  // namespace
}  // namespace roadscale::batch
