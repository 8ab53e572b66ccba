#include "roadscale/io/codecs_plugin.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

namespace {

void Decode(const unsigned char* bytes, size_t size, int flags, cv::Mat* image) {
  const cv::Mat buffer(1, static_cast<int>(size), CV_8UC1, const_cast<unsigned char*>(bytes));
  *image = cv::imdecode(buffer, flags);
}

bool Write(const char* path, const cv::Mat* image) { return cv::imwrite(path, *image); }

void* VideoOpen(const char* path) {
  auto* video = new cv::VideoCapture();
  if (video->open(path) && video->isOpened()) return video;
  delete video;
  return nullptr;
}

void VideoClose(void* video) { delete static_cast<cv::VideoCapture*>(video); }

double VideoGet(void* video, int property) {
  return static_cast<cv::VideoCapture*>(video)->get(property);
}

bool VideoGrab(void* video) { return static_cast<cv::VideoCapture*>(video)->grab(); }

bool VideoRetrieve(void* video, cv::Mat* image) {
  return static_cast<cv::VideoCapture*>(video)->retrieve(*image);
}

const RoadscaleCodecs kCodecs = {Decode,   Write,     VideoOpen,    VideoClose,
                                 VideoGet, VideoGrab, VideoRetrieve};

}  // namespace

extern "C" __attribute__((visibility("default"))) const RoadscaleCodecs* roadscale_codecs() {
  return &kCodecs;
}
