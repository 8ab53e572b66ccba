#include "roadscale/segmentation/label_image_segmenter.h"

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include "roadscale/segmentation/make_segmenter.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using testing::TempDir;
using testing::WriteTextFile;

class LabelImageSegmenterTest : public ::testing::Test {
 protected:
  // labels/000000.png: 30x20, road (train id 0 or label id 7) at the bottom, a car (13 or 26).
  std::string WriteExample(const std::string& ids, const std::string& extra = "") {
    const bool label_ids = ids == "label_ids";
    cv::Mat labels(20, 30, CV_8U, cv::Scalar(label_ids ? 11 : 2));
    labels.rowRange(15, 20).setTo(label_ids ? 7 : 0);
    labels(cv::Rect(10, 5, 4, 4)).setTo(label_ids ? 26 : 13);
    std::filesystem::create_directories(dir_.path() / "labels");
    cv::imwrite(dir_.File("labels/000000.png"), labels);
    return WriteTextFile(dir_.File("labels.yaml"),
                         "backend: label_images\nfolder: labels\nids: " + ids + "\n" + extra);
  }

  std::unique_ptr<Segmenter> Make(const std::string& yaml) {
    SegmentationOptions options;
    options.model = yaml;
    options.masks.dynamic_dilation_px = 0;
    return MakeSegmenter(options);
  }

  TempDir dir_;
  const cv::Mat image_ = cv::Mat(20, 30, CV_8U, cv::Scalar(50));
};

TEST_F(LabelImageSegmenterTest, ReadsTrainIds) {
  auto segmenter = Make(WriteExample("train_ids"));
  const SegmentationResult result = segmenter->Segment(image_, "000000");
  EXPECT_EQ(result.labels.at<uchar>(16, 0), 0);
  EXPECT_EQ(result.labels.at<uchar>(6, 11), 13);
  EXPECT_EQ(cv::countNonZero(result.road_mask), 30 * 5);
  EXPECT_EQ(cv::countNonZero(result.dynamic_mask), 16);
  EXPECT_EQ(cv::countNonZero(result.static_mask), 600 - 16);
}

TEST_F(LabelImageSegmenterTest, MapsCityscapesLabelIdsToTrainIds) {
  auto segmenter = Make(WriteExample("label_ids"));
  const SegmentationResult result = segmenter->Segment(image_, "000000");
  EXPECT_EQ(result.labels.at<uchar>(16, 0), 0);
  EXPECT_EQ(result.labels.at<uchar>(6, 11), 13);
  EXPECT_EQ(result.labels.at<uchar>(0, 0), 2);  // building: label id 11, train id 2
  EXPECT_EQ(cv::countNonZero(result.road_mask), 30 * 5);
}

TEST_F(LabelImageSegmenterTest, MissingFrameIsAnErrorNamingTheFile) {
  auto segmenter = Make(WriteExample("train_ids"));
  try {
    segmenter->CheckFrames({"000000", "000001"}, image_.size());
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("000001.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  }
  EXPECT_THROW(segmenter->Segment(image_, "000001"), Error);
}

TEST_F(LabelImageSegmenterTest, WrongSizeIsAnErrorUnlessResizeIsAllowed) {
  auto strict = Make(WriteExample("train_ids"));
  const cv::Mat bigger(40, 60, CV_8U, cv::Scalar(0));
  try {
    strict->CheckFrames({"000000"}, bigger.size());
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("30x20, expected the frame's size 60x40"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(strict->Segment(bigger, "000000"), Error);

  auto resizing = Make(WriteExample("train_ids", "resize: true\n"));
  EXPECT_NO_THROW(resizing->CheckFrames({"000000"}, bigger.size()));
  const SegmentationResult result = resizing->Segment(bigger, "000000");
  ASSERT_EQ(result.labels.size(), bigger.size());
  EXPECT_EQ(cv::countNonZero(result.road_mask), 60 * 10);
  EXPECT_EQ(cv::countNonZero(result.dynamic_mask), 64);
}

TEST_F(LabelImageSegmenterTest, ColourOrBrokenLabelFilesAreErrors) {
  const std::string yaml = WriteExample("train_ids");
  cv::imwrite(dir_.File("labels/000001.png"), cv::Mat(20, 30, CV_8UC3, cv::Scalar(0, 0, 0)));
  WriteTextFile(dir_.File("labels/000002.png"), "not a png");
  auto segmenter = Make(yaml);
  EXPECT_THROW(segmenter->Segment(image_, "000001"), Error);
  try {
    segmenter->CheckFrames({"000002"}, image_.size());
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not a PNG"), std::string::npos) << e.what();
  }
  EXPECT_THROW(segmenter->Segment(image_, "000002"), Error);
}

TEST_F(LabelImageSegmenterTest, MissingFolderIsAnError) {
  const std::string yaml = WriteTextFile(
      dir_.File("m.yaml"), "backend: label_images\nfolder: nowhere\nids: train_ids\n");
  EXPECT_THROW(Make(yaml), Error);
}

TEST(PngSize, ReadsTheHeader) {
  TempDir dir;
  cv::imwrite(dir.File("a.png"), cv::Mat(7, 1242, CV_8U, cv::Scalar(0)));
  EXPECT_EQ(ReadPngSize(dir.File("a.png")), cv::Size(1242, 7));
  EXPECT_THROW(ReadPngSize(dir.File("missing.png")), Error);
}

}  // namespace
}  // namespace roadscale
