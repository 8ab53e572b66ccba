#pragma once

#include <string>

#include <opencv2/core.hpp>

namespace roadscale {

// OpenCV's image decoding and writing and its video reader, from the codecs plugin, which is
// opened on the first call (codecs_plugin.h says why). The plugin is the file
// $ROADSCALE_CODECS_PLUGIN names when it is set, else, for code linked into a program (or
// module) inside the build tree, the one the build made, and for any other the one `cmake
// --install` put in LIBDIR/roadscale. Each function throws Error when the plugin cannot be
// opened.

// cv::imdecode of the file's bytes with cv::IMREAD_* `flags`; empty when they are no image.
cv::Mat DecodeImage(const std::string& bytes, int flags);
// cv::imwrite; false when it fails.
bool WriteImage(const std::string& path, const cv::Mat& image);

// cv::VideoCapture's reading of a video file.
class VideoReader {
 public:
  VideoReader() = default;
  ~VideoReader();
  VideoReader(const VideoReader&) = delete;
  VideoReader& operator=(const VideoReader&) = delete;

  // False when the file does not open as a video.
  bool Open(const std::string& path);
  // cv::CAP_PROP_* `property` of the open video.
  double Get(int property) const;
  bool Grab();
  bool Retrieve(cv::Mat* image);

 private:
  void* video_ = nullptr;
};

}  // namespace roadscale
