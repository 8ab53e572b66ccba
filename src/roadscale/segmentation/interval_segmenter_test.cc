#include "roadscale/segmentation/interval_segmenter.h"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// Label map filled with the number of the call, so that a result tells which call made it.
class CountingSegmenter : public Segmenter {
 public:
  explicit CountingSegmenter(std::vector<std::string>* names) : names_(names) {}
  SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) override {
    names_->push_back(frame_name);
    SegmentationResult result;
    result.labels = cv::Mat(image.size(), CV_8U, cv::Scalar(static_cast<int>(names_->size())));
    result.milliseconds = 1.0;
    return result;
  }
  std::string Description() const override { return "counting"; }

 private:
  std::vector<std::string>* names_;
};

TEST(IntervalSegmenter, SegmentsEveryKthFrameAndReusesTheLastResult) {
  std::vector<std::string> names;
  IntervalSegmenter segmenter(std::make_unique<CountingSegmenter>(&names), 3);
  const cv::Mat image(4, 6, CV_8U, cv::Scalar(0));
  std::vector<int> made_by;
  std::vector<bool> fresh;
  for (int frame = 0; frame < 7; ++frame) {
    const SegmentationResult result = segmenter.Segment(image, std::to_string(frame));
    made_by.push_back(result.labels.at<uchar>(0, 0));
    fresh.push_back(result.fresh);
    EXPECT_EQ(result.milliseconds, result.fresh ? 1.0 : 0.0);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"0", "3", "6"}));
  EXPECT_EQ(made_by, (std::vector<int>{1, 1, 1, 2, 2, 2, 3}));
  EXPECT_EQ(fresh, (std::vector<bool>{true, false, false, true, false, false, true}));
  EXPECT_EQ(segmenter.Description(), "counting, every 3 frames");
}

TEST(IntervalSegmenter, EveryFrameWhenKIsOneOrTheImageSizeChanges) {
  std::vector<std::string> names;
  IntervalSegmenter segmenter(std::make_unique<CountingSegmenter>(&names), 5);
  segmenter.Segment(cv::Mat(4, 6, CV_8U), "a");
  segmenter.Segment(cv::Mat(4, 6, CV_8U), "b");
  const SegmentationResult result = segmenter.Segment(cv::Mat(8, 6, CV_8U), "c");
  EXPECT_EQ(names, (std::vector<std::string>{"a", "c"}));
  EXPECT_EQ(result.labels.rows, 8);

  std::vector<std::string> every_names;
  IntervalSegmenter every(std::make_unique<CountingSegmenter>(&every_names), 1);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(every.Segment(cv::Mat(2, 2, CV_8U), "x").fresh);
  EXPECT_EQ(every_names.size(), 3u);
}

TEST(IntervalSegmenter, RejectsKBelowOne) {
  std::vector<std::string> names;
  EXPECT_THROW(IntervalSegmenter(std::make_unique<CountingSegmenter>(&names), 0), Error);
}

}  // namespace
}  // namespace roadscale
