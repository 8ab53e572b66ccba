#include "roadscale/pipeline/segmentation_service.h"

#include "roadscale/pipeline/thread_cpu_time.h"
#include "roadscale/util/error.h"

namespace roadscale {

SegmentationService::SegmentationService(const std::vector<Segmenter*>& segmenters, bool threaded)
    : segmenters_(segmenters), threaded_(threaded) {
  CheckOption(!segmenters_.empty(), "segmenters", "at least one segmenter is needed");
  if (!threaded_) return;
  for (Segmenter* segmenter : segmenters_) {
    workers_.emplace_back([this, segmenter] { Work(*segmenter); });
  }
}

SegmentationService::~SegmentationService() {
  Cancel();
  for (std::thread& worker : workers_) worker.join();
}

ServedSegmentation SegmentationService::Run(Segmenter& segmenter, const Request& request) {
  const double start = ThreadCpuMs();
  ServedSegmentation served;
  served.result = segmenter.Segment(request.image, request.name);
  served.cpu_ms = ThreadCpuMs() - start;
  return served;
}

void SegmentationService::Submit(size_t frame_index, const cv::Mat& image,
                                 const std::string& frame_name) {
  const std::lock_guard<std::mutex> lock(mutex_);
  entries_[frame_index] = Entry();
  Request request{frame_index, image, frame_name};
  if (threaded_) {
    requests_.push_back(std::move(request));
    changed_.notify_all();
  } else {
    deferred_.emplace(frame_index, std::move(request));
  }
}

void SegmentationService::Work(Segmenter& segmenter) {
  while (true) {
    Request request;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return cancelled_ || !requests_.empty(); });
      if (cancelled_) return;
      request = std::move(requests_.front());
      requests_.pop_front();
    }
    Entry entry;
    try {
      entry.served = Run(segmenter, request);
    } catch (...) {
      entry.error = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    Entry& stored = entries_[request.frame_index];
    stored.served = std::move(entry.served);
    stored.error = entry.error;
    stored.done = true;
    changed_.notify_all();
  }
}

ServedSegmentation SegmentationService::Take(size_t frame_index) {
  std::unique_lock<std::mutex> lock(mutex_);
  const auto entry = entries_.find(frame_index);
  if (entry == entries_.end()) {
    throw Error("segmentation of frame " + std::to_string(frame_index) +
                " taken but never submitted (internal error)");
  }
  if (!threaded_ && !entry->second.done) {
    const auto request = deferred_.find(frame_index);
    try {
      entry->second.served = Run(*segmenters_.front(), request->second);
    } catch (...) {
      entry->second.error = std::current_exception();
    }
    entry->second.done = true;
    deferred_.erase(request);
  }
  changed_.wait(lock, [&] { return cancelled_ || entry->second.done; });
  if (!entry->second.done) throw Error("segmentation stopped");
  if (entry->second.error) std::rethrow_exception(entry->second.error);
  ServedSegmentation served = entry->second.served;
  if (--entry->second.reads_left == 0) entries_.erase(entry);
  return served;
}

void SegmentationService::Cancel() {
  const std::lock_guard<std::mutex> lock(mutex_);
  cancelled_ = true;
  changed_.notify_all();
}

}  // namespace roadscale
