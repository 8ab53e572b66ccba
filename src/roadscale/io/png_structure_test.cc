#include "roadscale/io/png_structure.h"

#include <vector>

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

namespace roadscale {
namespace {

std::string EncodedPng() {
  cv::Mat image(24, 32, CV_8UC1);
  cv::randu(image, 0, 256);
  std::vector<uchar> buffer;
  cv::imencode(".png", image, buffer);
  return std::string(buffer.begin(), buffer.end());
}

TEST(PngStructure, AWholePngPasses) { EXPECT_EQ(PngStructureProblem(EncodedPng()), ""); }

TEST(PngStructure, TruncatedOrDamagedFilesAreNamed) {
  const std::string png = EncodedPng();
  EXPECT_EQ(PngStructureProblem(png.substr(0, png.size() - 12)), "no IEND chunk (truncated)");
  EXPECT_EQ(PngStructureProblem(png.substr(0, 60)).rfind("truncated in chunk ", 0), 0u);
  EXPECT_EQ(PngStructureProblem(png.substr(0, 10)), "truncated in a chunk header");
  std::string flipped = png;
  flipped[50] = static_cast<char>(flipped[50] ^ 0x01);
  EXPECT_EQ(PngStructureProblem(flipped).rfind("checksum mismatch in chunk ", 0), 0u);
  // A huge length field must not be trusted.
  std::string long_chunk = png;
  long_chunk[8] = '\xff';
  EXPECT_EQ(PngStructureProblem(long_chunk), "truncated in chunk IHDR");
}

TEST(PngStructure, OtherFilesAreLeftToTheDecoder) {
  EXPECT_EQ(PngStructureProblem("\xff\xd8\xff\xe0 a JPEG"), "");
  EXPECT_EQ(PngStructureProblem(""), "");
}

}  // namespace
}  // namespace roadscale
