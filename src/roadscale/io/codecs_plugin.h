#pragma once

#include <cstddef>

#include <opencv2/core.hpp>

// The table of functions the codecs plugin (codecs_plugin.cc, a shared object of its own)
// exports through kCodecsEntryPoint: OpenCV's image and video readers, which load about 200
// shared libraries (GDAL, GDCM, GStreamer, FFmpeg...; 263 in the command with them, 57
// without), 0.2 s of every process's start on a 2-core machine, whether or not it reads an
// image. image_codecs.h opens the plugin on the
// first image read or written (docs/benchmark-history.md, "What a process pays before main:
// OpenCV's image and video readers").
struct RoadscaleCodecs {
  // cv::imdecode of `size` bytes with cv::IMREAD_* `flags` into `image` (empty on failure).
  void (*decode)(const unsigned char* bytes, size_t size, int flags, cv::Mat* image);
  // cv::imwrite; false when it fails.
  bool (*write)(const char* path, const cv::Mat* image);
  // A cv::VideoCapture on `path` (null when it does not open), and its members.
  void* (*video_open)(const char* path);
  void (*video_close)(void* video);
  double (*video_get)(void* video, int property);
  bool (*video_grab)(void* video);
  bool (*video_retrieve)(void* video, cv::Mat* image);
};

// The plugin's one exported symbol: a function returning the table.
inline constexpr const char kCodecsEntryPoint[] = "roadscale_codecs";
using CodecsEntryPoint = const RoadscaleCodecs* (*)();
