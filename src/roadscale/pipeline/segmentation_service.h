#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// A segmented frame's result and the CPU time of the segmenter's thread for it.
struct ServedSegmentation {
  SegmentationResult result;
  double cpu_ms = 0.0;
};

// Segments the frames the schedule picks: on one worker thread per segmenter (whichever is
// free), or, without threads, when the result is first asked for. Each result is read by two
// stages (the frontend, for its carried masks, and the scale stage, for the road mask) and
// freed after the second read.
class SegmentationService {
 public:
  SegmentationService(const std::vector<Segmenter*>& segmenters, bool threaded);
  ~SegmentationService();
  SegmentationService(const SegmentationService&) = delete;
  SegmentationService& operator=(const SegmentationService&) = delete;

  void Submit(size_t frame_index, const cv::Mat& image, const std::string& frame_name);
  // Waits for the frame's result; rethrows the segmenter's error. Each submitted frame must
  // be taken exactly twice.
  ServedSegmentation Take(size_t frame_index);
  // Stops the workers; Take then throws.
  void Cancel();

 private:
  struct Request {
    size_t frame_index = 0;
    cv::Mat image;
    std::string name;
  };
  struct Entry {
    bool done = false;
    int reads_left = 2;
    ServedSegmentation served;
    std::exception_ptr error;
  };
  void Work(Segmenter& segmenter);
  static ServedSegmentation Run(Segmenter& segmenter, const Request& request);

  std::vector<Segmenter*> segmenters_;
  bool threaded_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Request> requests_;
  std::map<size_t, Request> deferred_;  // without threads: segmented when first taken
  std::map<size_t, Entry> entries_;
  bool cancelled_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace roadscale
