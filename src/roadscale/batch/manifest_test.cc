#include "roadscale/batch/manifest.h"

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
using ::testing::HasSubstr;

// A manifest in `dir` with a KITTI-like folder seq/ and a camera file beside it.
class ManifestTest : public ::testing::Test {
 protected:
  ManifestTest() {
    std::filesystem::create_directories(dir_.path() / "seq");
    std::filesystem::create_directories(dir_.path() / "frames");
    WriteTextFile(dir_.File("cam.yaml"), "Camera: {}\n");
  }

  std::string Write(const std::string& text) { return WriteTextFile(dir_.File("m.yaml"), text); }

  // The message of the Error that reading `text` throws, or "no error".
  std::string ErrorOf(const std::string& text) {
    try {
      ReadBatchManifest(Write(text));
    } catch (const Error& error) {
      return error.what();
    }
    return "no error";
  }

  TempDir dir_;
};

TEST_F(ManifestTest, ReadsDrivesWithPathsRelativeToTheManifest) {
  const BatchManifest manifest =
      ReadBatchManifest(Write("drives:\n"
                              "  - name: a\n"
                              "    kitti: seq\n"
                              "    frames: \"0:20\"\n"
                              "    h0: 1.5\n"
                              "    no_segmentation: true\n"
                              "  - name: b\n"
                              "    images: frames\n"
                              "    camera: cam.yaml\n"
                              "    detector: orb\n"
                              "    scale: oracle\n"
                              "    sequential: true\n"));
  ASSERT_EQ(manifest.drives.size(), 2U);
  const BatchDrive& a = manifest.drives[0];
  EXPECT_EQ(a.name, "a");
  EXPECT_EQ(a.kitti, (dir_.path() / "seq").string());
  EXPECT_EQ(a.frames, "0:20");
  EXPECT_EQ(a.h0, 1.5);
  EXPECT_TRUE(a.no_segmentation);
  const BatchDrive& b = manifest.drives[1];
  EXPECT_EQ(b.images, (dir_.path() / "frames").string());
  EXPECT_EQ(b.camera, dir_.File("cam.yaml"));
  EXPECT_EQ(b.detector, "orb");
  EXPECT_EQ(b.scale, "oracle");
  EXPECT_TRUE(b.sequential);
  EXPECT_FALSE(b.h0);
}

TEST_F(ManifestTest, UnknownKeyIsAnErrorNamingFileLineAndKey) {
  const std::string message = ErrorOf("drives:\n  - name: a\n    kitti: seq\n    frame: 0:20\n");
  EXPECT_THAT(message, HasSubstr("m.yaml:4: unknown key 'frame' (expected one of"));
  EXPECT_THAT(ErrorOf("drive:\n  - name: a\n"), HasSubstr("m.yaml:1: unknown key 'drive'"));
}

TEST_F(ManifestTest, MissingFolderOrFileIsAnError) {
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: nowhere\n"),
              HasSubstr("m.yaml:3: kitti folder '" + (dir_.path() / "nowhere").string() +
                        "' does not exist"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: cam.yaml\n"),
              HasSubstr("m.yaml:3: kitti '" + dir_.File("cam.yaml") + "' is not a folder"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    images: frames\n    camera: nocam.yaml\n"),
              HasSubstr("m.yaml:4: camera file '" + dir_.File("nocam.yaml") + "' does not exist"));
}

TEST_F(ManifestTest, DuplicateNameIsAnErrorNamingBothLines) {
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: seq\n  - name: a\n    kitti: seq\n"),
              HasSubstr("m.yaml:4: drive name 'a' appears twice (first on line 2)"));
}

TEST_F(ManifestTest, DriveNeedsANameAndExactlyOneInput) {
  EXPECT_THAT(ErrorOf("drives:\n  - kitti: seq\n"), HasSubstr("m.yaml:2: a drive without name:"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n"),
              HasSubstr("drive 'a': give exactly one of kitti, images, video"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: seq\n    images: frames\n"),
              HasSubstr("drive 'a': give exactly one of kitti, images, video"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    images: frames\n"),
              HasSubstr("drive 'a': images and video need camera:"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a/b\n    kitti: seq\n"),
              HasSubstr("m.yaml:2: drive 'a/b': a drive's name must be a folder name"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: slurm\n    kitti: seq\n"),
              HasSubstr("'slurm' is the folder of the Slurm scripts"));
  // A drive named after the batch's own files wrote its outputs over them (issue 30, defect 9).
  for (const std::string name :
       {"batch.json", "summary.md", "summary.csv", "summary.json", "summary.html", "Summary.MD"}) {
    EXPECT_THAT(ErrorOf("drives:\n  - name: " + name + "\n    kitti: seq\n"),
                HasSubstr("m.yaml:2: drive '" + name + "': '"))
        << name;
  }
  EXPECT_THAT(ErrorOf("drives:\n  - name: SLURM\n    kitti: seq\n"),
              HasSubstr("'slurm' is the folder of the Slurm scripts"));
}

TEST_F(ManifestTest, ValuesRunWouldRefuseAreErrorsHere) {
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: seq\n    frames: 5:2\n"),
              HasSubstr("m.yaml:4: "));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: seq\n    scale: magic\n"),
              HasSubstr("m.yaml:4: unknown scale 'magic' (expected road or oracle)"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: seq\n    h0: -1\n"),
              HasSubstr("m.yaml:4: h0: expected a camera height"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: seq\n    sequential: maybe\n"),
              HasSubstr("m.yaml:4: sequential: expected true or false"));
  EXPECT_THAT(ErrorOf("drives:\n  - name: a\n    kitti: seq\n    detector: eyes\n"),
              HasSubstr("m.yaml:4: "));
  EXPECT_THAT(ErrorOf("drives: []\n"), HasSubstr("m.yaml:1: drives: expected a list"));
  EXPECT_THAT(ErrorOf(""), HasSubstr("m.yaml: expected a mapping with drives:"));
}

TEST(SequenceListTest, RangesAndListsKeepTheirWidth) {
  EXPECT_THAT(ParseSequenceList("00-03"), ElementsAre("00", "01", "02", "03"));
  EXPECT_THAT(ParseSequenceList("00,02,09-10"), ElementsAre("00", "02", "09", "10"));
  EXPECT_THAT(ParseSequenceList("7"), ElementsAre("7"));
  EXPECT_THROW(ParseSequenceList("03-01"), Error);
  EXPECT_THROW(ParseSequenceList("00,00"), Error);
  EXPECT_THROW(ParseSequenceList("00-"), Error);
  EXPECT_THROW(ParseSequenceList("x"), Error);
  EXPECT_THROW(ParseSequenceList(""), Error);
}

TEST(KittiManifestTest, OneDrivePerSequenceFolder) {
  TempDir root;
  std::filesystem::create_directories(root.path() / "sequences" / "00");
  std::filesystem::create_directories(root.path() / "sequences" / "01");
  const BatchManifest manifest = KittiBatchManifest(root.path().string(), "00-01");
  ASSERT_EQ(manifest.drives.size(), 2U);
  EXPECT_EQ(manifest.drives[1].name, "01");
  EXPECT_EQ(manifest.drives[1].kitti, (root.path() / "sequences" / "01").string());
  try {
    KittiBatchManifest(root.path().string(), "00-02");
    ADD_FAILURE() << "sequence 02 is missing";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), HasSubstr("sequences/02: no such KITTI sequence folder"));
  }
}

}  // namespace
}  // namespace roadscale::batch
