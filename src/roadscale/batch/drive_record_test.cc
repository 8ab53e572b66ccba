#include "roadscale/batch/drive_record.h"

#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale::batch {
namespace {

using roadscale::testing::TempDir;
using roadscale::testing::WriteTextFile;
using ::testing::ElementsAre;

// A drive folder holding run's outputs and the record of a finished run with fingerprint "f1".
class FinishedDriveTest : public ::testing::Test {
 protected:
  FinishedDriveTest() {
    // Three frames: as many pose rows in each file, frames.csv with its header.
    for (const char* name : {"poses_kitti.txt", "poses_tum.txt", "gt_poses_kitti.txt"}) {
      WriteTextFile(dir_.File(name), "p\np\np\n");
    }
    WriteTextFile(dir_.File("frames.csv"), "frame\n0\n1\n2\n");
    for (const char* name : {"config_used.yaml", "report.html", "metrics.json"}) {
      WriteTextFile(dir_.File(name), "x\n");
    }
    record_.name = "a";
    record_.fingerprint = "f1";
    record_.arguments = {"run", "--kitti", "/seq", "--out", dir_.path().string()};
    record_.wall_s = 12.5;
    record_.outputs = RunOutputsIn(dir_.path().string());
    WriteDriveRecord(dir_.path().string(), record_);
  }

  std::string dir() const { return dir_.path().string(); }

  TempDir dir_;
  DriveRecord record_;
};

TEST_F(FinishedDriveTest, RecordReadsBackAsWritten) {
  const std::optional<DriveRecord> read = ReadDriveRecord(dir());
  ASSERT_TRUE(read);
  EXPECT_EQ(read->name, "a");
  EXPECT_EQ(read->fingerprint, "f1");
  EXPECT_EQ(read->arguments, record_.arguments);
  EXPECT_EQ(read->wall_s, 12.5);
  EXPECT_FALSE(read->interrupted);
  EXPECT_THAT(read->outputs,
              ElementsAre("poses_kitti.txt", "poses_tum.txt", "frames.csv", "config_used.yaml",
                          "report.html", "metrics.json", "gt_poses_kitti.txt"));
}

TEST_F(FinishedDriveTest, SameFingerprintWithAllOutputsIsFinished) {
  EXPECT_TRUE(IsDriveFinished(dir(), "f1"));
}

TEST_F(FinishedDriveTest, ChangedFingerprintIsRunAgain) {
  EXPECT_FALSE(IsDriveFinished(dir(), "f2"));
}

TEST_F(FinishedDriveTest, AMissingOutputIsRunAgain) {
  std::filesystem::remove(dir_.File("metrics.json"));
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
}

TEST_F(FinishedDriveTest, AFailedRunIsRunAgain) {
  record_.exit_status = 1;
  WriteDriveRecord(dir(), record_);
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
}

TEST_F(FinishedDriveTest, ARemovedRecordIsRunAgain) {
  RemoveDriveRecord(dir());
  EXPECT_FALSE(ReadDriveRecord(dir()));
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
}

TEST_F(FinishedDriveTest, ABrokenRecordIsAnErrorNamingItAndRunsAgain) {
  WriteTextFile(dir_.File(kDriveRecordFile), "{\"name\": \"a\"\n");
  EXPECT_THROW(ReadDriveRecord(dir()), Error);
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));  // it stopped the whole batch (issue 30)
}

// Resuming trusted the record and the files' presence, not their content (issue 30).
TEST_F(FinishedDriveTest, ARecordCutDownToFewerOutputsIsRunAgain) {
  record_.outputs = {"report.html"};
  WriteDriveRecord(dir(), record_);
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
}

TEST_F(FinishedDriveTest, TruncatedOrDisagreeingOutputsAreRunAgain) {
  WriteTextFile(dir_.File("poses_kitti.txt"), "p\np\n");  // a row short
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
  WriteTextFile(dir_.File("poses_kitti.txt"), "p\np\np");  // the last row cut
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
  WriteTextFile(dir_.File("poses_kitti.txt"), "p\np\np\n");
  EXPECT_TRUE(IsDriveFinished(dir(), "f1"));
  WriteTextFile(dir_.File("frames.csv"), "frame\n0\n1\n");
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
  WriteTextFile(dir_.File("frames.csv"), "frame\n0\n1\n2\n");
  WriteTextFile(dir_.File("gt_poses_kitti.txt"), "p\n");
  EXPECT_FALSE(IsDriveFinished(dir(), "f1"));
}

TEST(LastErrorLineTest, TakesTheLastErrorOfTheLog) {
  TempDir dir;
  const std::string log = WriteTextFile(
      dir.File("run.log"),
      "Input: x\nroadscale: error: first\nroadscale: note: y\nroadscale: error: cfg.yaml:3: bad\n");
  EXPECT_EQ(LastErrorLine(log), "cfg.yaml:3: bad");
  WriteTextFile(log, "roadscale: internal error: boom\n");
  EXPECT_EQ(LastErrorLine(log), "internal error: boom");
  WriteTextFile(log, "all fine\n");
  EXPECT_EQ(LastErrorLine(log), "");
}

}  // namespace
}  // namespace roadscale::batch
