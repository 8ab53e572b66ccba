#include "roadscale/batch/batch_folder.h"

#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/batch/drive_record.h"
#include "roadscale/testing/error_of.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

using roadscale::testing::ErrorOf;
using roadscale::testing::TempDir;
using roadscale::testing::WriteTextFile;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

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

// --summarize used batch.json's names as paths ("../../../etc") and as text (issue 30).
TEST(BatchFolderTest, NamesNoDriveCanHaveAreRefusedOrSkipped) {
  TempDir batch;
  WriteTextFile(batch.File("batch.json"), R"({"drives": ["a", "../../../etc"]})");
  EXPECT_THAT(ErrorOf([&] { DriveNamesIn(batch.path().string()); }),
              HasSubstr(batch.File("batch.json") + ": drive '../../../etc': a drive's name must"));
  WriteTextFile(batch.File("batch.json"), R"({"drives": ["<b>x</b>"]})");
  EXPECT_THROW(DriveNamesIn(batch.path().string()), Error);
  std::filesystem::remove(batch.File("batch.json"));
  WriteRecordOf(batch, "a");
  WriteRecordOf(batch, "a b");
  EXPECT_THAT(DriveNamesIn(batch.path().string()), ElementsAre("a"));
}

TEST(BatchFolderTest, MissingFolderIsAnError) {
  TempDir batch;
  EXPECT_THROW(DriveNamesIn(batch.File("nowhere")), Error);
}

}  // namespace
}  // namespace roadscale::batch
