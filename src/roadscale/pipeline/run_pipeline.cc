#include "roadscale/pipeline/run_pipeline.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <thread>

#include <opencv2/core/utility.hpp>

#include "roadscale/pipeline/bounded_queue.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using Clock = std::chrono::steady_clock;

double MillisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool IsImageFile(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".png" || extension == ".jpg" || extension == ".jpeg";
}

// Stage 1: the next frame and its segmentation; false after the last frame.
bool LoadAndSegment(FrameSource& source, Segmenter& segmenter, SegmentedFrame* out) {
  const Clock::time_point start = Clock::now();
  if (!source.Next(&out->frame)) return false;
  out->load_ms = MillisecondsSince(start);
  out->segmentation = segmenter.Segment(out->frame.image, FrameName(out->frame));
  return true;
}

// The stages on one thread, one frame after the other.
// Returns whether the run was interrupted.
bool RunSequentially(FrameSource& source, Segmenter& segmenter, SequentialPipeline& pipeline,
                     const std::atomic<bool>* stop) {
  SegmentedFrame frame;
  while (true) {
    if (stop != nullptr && stop->load()) return true;
    if (!LoadAndSegment(source, segmenter, &frame)) return false;
    pipeline.Integrate(pipeline.Track(frame));
  }
}

// Stage 1 and stage 2 on their own threads, stage 3 on the calling thread. Returns whether
// the run was interrupted.
bool RunThreaded(FrameSource& source, Segmenter& segmenter, SequentialPipeline& pipeline,
                 const RunPipelineOptions& options, const std::atomic<bool>* stop) {
  BoundedQueue<SegmentedFrame> segmented(options.queue_capacity);
  BoundedQueue<TrackedFrame> tracked(options.queue_capacity);
  std::exception_ptr segmentation_error;
  std::exception_ptr frontend_error;
  std::exception_ptr integration_error;
  std::atomic<bool> interrupted{false};

  std::thread segmentation_thread([&] {
    try {
      while (true) {
        if (stop != nullptr && stop->load()) {
          interrupted = true;
          break;
        }
        SegmentedFrame frame;
        if (!LoadAndSegment(source, segmenter, &frame)) break;
        if (!segmented.Push(std::move(frame))) break;
      }
    } catch (...) {
      segmentation_error = std::current_exception();
    }
    segmented.Close();
  });
  std::thread frontend_thread([&] {
    try {
      while (std::optional<SegmentedFrame> frame = segmented.Pop()) {
        if (!tracked.Push(pipeline.Track(*frame))) break;
      }
    } catch (...) {
      frontend_error = std::current_exception();
      segmented.Cancel();
    }
    tracked.Close();
  });

  try {
    while (std::optional<TrackedFrame> frame = tracked.Pop()) {
      pipeline.Integrate(std::move(*frame));
    }
  } catch (...) {
    integration_error = std::current_exception();
    tracked.Cancel();
    segmented.Cancel();
  }
  frontend_thread.join();
  segmentation_thread.join();
  // The latest stage's error first: it stopped the run at the earliest frame.
  if (integration_error) std::rethrow_exception(integration_error);
  if (frontend_error) std::rethrow_exception(frontend_error);
  if (segmentation_error) std::rethrow_exception(segmentation_error);
  return interrupted.load();
}

}  // namespace

void RunPipelineOptions::Check() const {
  CheckOption(queue_capacity >= 1, "queue_capacity", "must be >= 1");
  CheckOption(opencv_threads >= 0, "opencv_threads", "must be >= 0 (0: leave OpenCV's)");
}

std::string FrameName(const Frame& frame) {
  if (IsImageFile(frame.path)) return std::filesystem::path(frame.path).stem().string();
  char name[32];
  std::snprintf(name, sizeof(name), "%06zu", frame.index);
  return name;
}

PipelineRunResult RunPipeline(FrameSource& source, Segmenter& segmenter, ScaleSource& scale,
                              const PipelineOptions& options, const std::string& out_dir,
                              const RunPipelineOptions& run_options,
                              const std::function<void(const FrameRecord&)>& on_frame,
                              const std::atomic<bool>* stop) {
  run_options.Check();
  SequentialPipeline pipeline(source.camera(), scale, options, out_dir);
  PipelineRunResult result;
  pipeline.SetWrittenCallback([&](const FrameRecord& record) {
    result.summary.Add(record);
    if (on_frame) on_frame(record);
  });
  const Clock::time_point start = Clock::now();
  result.interrupted = run_options.threaded
                           ? RunThreaded(source, segmenter, pipeline, run_options, stop)
                           : RunSequentially(source, segmenter, pipeline, stop);
  pipeline.Finish();
  result.summary.wall_s = MillisecondsSince(start) / 1000.0;
  return result;
}

}  // namespace roadscale
