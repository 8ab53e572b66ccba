#include "roadscale/io/image_file.h"

#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "roadscale/testing/error_of.h"
#include "roadscale/testing/temp_dir.h"

namespace roadscale {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using ::testing::Not;

cv::Mat RandomImage() {
  cv::Mat image(24, 32, CV_8UC3);
  cv::randu(image, 0, 256);
  return image;
}

TEST(ImageFile, WritesWhatItReadsBack) {
  const testing::TempDir dir;
  const cv::Mat image = RandomImage();
  WriteImageFile(dir.File("a.png"), image);
  const cv::Mat read = ReadImageFile(dir.File("a.png"), cv::IMREAD_COLOR, "image");
  ASSERT_EQ(read.size(), image.size());
  EXPECT_EQ(cv::norm(read, image, cv::NORM_INF), 0.0);
}

TEST(ImageFile, AFailedWriteIsOneLineNamingTheFile) {
  const testing::TempDir dir;
  const std::string no_folder = dir.File("missing/a.png");
  const std::string error = ErrorOf([&] { WriteImageFile(no_folder, RandomImage()); });
  EXPECT_EQ(error, no_folder + ": cannot write image: no such file or directory");
  // OpenCV throws for a format it has no writer for; its message is not passed on.
  const std::string unknown = dir.File("a.unknown_format");
  const std::string thrown = ErrorOf([&] { WriteImageFile(unknown, RandomImage()); });
  EXPECT_EQ(thrown, unknown + ": cannot write image");
  EXPECT_THAT(thrown, Not(HasSubstr("\n")));
  EXPECT_FALSE(std::filesystem::exists(unknown));
}

}  // namespace
}  // namespace roadscale
