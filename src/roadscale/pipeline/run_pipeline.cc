#include "roadscale/pipeline/run_pipeline.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <opencv2/core/utility.hpp>

#include "roadscale/pipeline/bounded_queue.h"
#include "roadscale/pipeline/carried_segmentation_run.h"
#include "roadscale/pipeline/run_output_files.h"
#include "roadscale/pipeline/stage_thread.h"
#include "roadscale/pipeline/thread_cpu_time.h"
#include "roadscale/util/elapsed_time.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using Clock = std::chrono::steady_clock;

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
  const double cpu_start = ThreadCpuMs();
  out->segmentation = segmenter.Segment(out->frame.image, FrameName(out->frame));
  out->segmentation_cpu_ms = ThreadCpuMs() - cpu_start;
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

// Stage 1 on one thread per segmenter, stage 2 on its own thread, stage 3 on the calling
// thread. Returns whether the run was interrupted.
bool RunThreaded(FrameSource& source, const std::vector<Segmenter*>& segmenters,
                 SequentialPipeline& pipeline, const std::atomic<bool>* stop) {
  BoundedQueue<SegmentedFrame> segmented(kStageQueueCapacity);
  BoundedQueue<TrackedFrame> tracked(kStageQueueCapacity);
  std::atomic<bool> interrupted{false};

  // Stage 1: each worker takes the next frame from the source (in turn), segments it with
  // its own segmenter, and the frames go on in their order: at most one frame per worker
  // waits for an earlier one.
  std::mutex source_mutex;
  bool no_more_frames = false;  // the source is done, or a worker failed or was cancelled
  size_t frames_taken = 0;
  std::mutex order_mutex;
  std::map<size_t, SegmentedFrame> finished;
  size_t next_to_hand_on = 0;
  std::atomic<size_t> workers_running{segmenters.size()};
  const auto stop_taking_frames = [&] {
    const std::lock_guard<std::mutex> lock(source_mutex);
    no_more_frames = true;
  };
  const auto segment_frames = [&](Segmenter& segmenter) {
    while (true) {
      if (stop != nullptr && stop->load()) {
        interrupted = true;
        return;
      }
      SegmentedFrame frame;
      size_t sequence = 0;
      {
        const std::lock_guard<std::mutex> lock(source_mutex);
        if (no_more_frames) return;
        const Clock::time_point start = Clock::now();
        if (!source.Next(&frame.frame)) {
          no_more_frames = true;
          return;
        }
        frame.load_ms = MillisecondsSince(start);
        sequence = frames_taken++;
      }
      const double cpu_start = ThreadCpuMs();
      frame.segmentation = segmenter.Segment(frame.frame.image, FrameName(frame.frame));
      frame.segmentation_cpu_ms = ThreadCpuMs() - cpu_start;
      const std::lock_guard<std::mutex> lock(order_mutex);
      finished.emplace(sequence, std::move(frame));
      for (auto next = finished.find(next_to_hand_on); next != finished.end();
           next = finished.find(next_to_hand_on)) {
        const bool handed_on = segmented.Push(std::move(next->second));
        finished.erase(next);
        ++next_to_hand_on;
        if (!handed_on) {
          stop_taking_frames();
          return;
        }
      }
    }
  };
  std::vector<std::unique_ptr<StageThread>> workers;
  for (Segmenter* segmenter : segmenters) {
    workers.push_back(std::make_unique<StageThread>([&, segmenter] { segment_frames(*segmenter); },
                                                    stop_taking_frames,
                                                    [&] {
                                                      if (--workers_running == 0) segmented.Close();
                                                    }));
  }
  const std::unique_ptr<StageThread> frontend_stage = StartQueueStage(
      segmented, tracked, [&](const SegmentedFrame& frame) { return pipeline.Track(frame); });

  const std::exception_ptr integration_error = RunFinalStage(
      [&] {
        while (std::optional<TrackedFrame> frame = tracked.Pop()) {
          pipeline.Integrate(std::move(*frame));
        }
      },
      [&] {
        tracked.Cancel();
        segmented.Cancel();
      });
  std::vector<std::exception_ptr> errors = {integration_error, frontend_stage->Join()};
  for (const std::unique_ptr<StageThread>& worker : workers) errors.push_back(worker->Join());
  RethrowFirstError(errors);
  return interrupted.load();
}

}  // namespace

void RunPipelineOptions::Check() const {
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
                              const RunPipelineOptions& run_options, const FrameOutput& on_frame,
                              const std::atomic<bool>* stop,
                              const ProvisionalOutput& on_provisional) {
  return RunPipeline(source, std::vector<Segmenter*>{&segmenter}, scale, options, out_dir,
                     run_options, on_frame, stop, on_provisional);
}

PipelineRunResult RunPipeline(FrameSource& source, const std::vector<Segmenter*>& segmenters,
                              ScaleSource& scale, const PipelineOptions& options,
                              const std::string& out_dir, const RunPipelineOptions& run_options,
                              const FrameOutput& on_frame, const std::atomic<bool>* stop,
                              const ProvisionalOutput& on_provisional) {
  run_options.Check();
  CheckOption(!segmenters.empty(), "segmenters", "at least one segmenter is needed");
  // Before any thread starts: OpenCV's thread count is one process-wide setting, and
  // changing it while another thread runs an OpenCV parallel loop crashes or hangs OpenCV.
  const int previous_opencv_threads = cv::getNumThreads();
  if (run_options.opencv_threads > 0) cv::setNumThreads(run_options.opencv_threads);
  struct RestoreOpenCvThreads {
    int threads;
    ~RestoreOpenCvThreads() {
      if (cv::getNumThreads() != threads) cv::setNumThreads(threads);
    }
  } restore_opencv_threads{previous_opencv_threads};
  SequentialPipeline pipeline(source.camera(), scale, options);
  std::optional<RunOutputFiles> files;
  if (!out_dir.empty()) files.emplace(out_dir, pipeline.DiagnosticsCsvHeader());
  PipelineRunResult result;
  pipeline.SetOutput([&](const FrameRecord& record, const Rigid3d& world_from_cam) {
    if (files) files->Write(record, world_from_cam);
    result.summary.Add(record);
    if (on_frame) on_frame(record, world_from_cam);
  });
  pipeline.SetProvisionalOutput(on_provisional);
  const Clock::time_point start = Clock::now();
  const double cpu_start = ProcessCpuMs();
  // Without segmentation there is nothing to schedule or carry.
  const bool carried = options.segmentation_schedule.mode == SegmentationScheduleMode::kKeyframes &&
                       dynamic_cast<const NoSegmenter*>(segmenters.front()) == nullptr;
  try {
    if (carried) {
      result.interrupted =
          RunWithCarriedMasks(source, segmenters, pipeline, options, run_options, stop);
    } else {
      result.interrupted = run_options.threaded
                               ? RunThreaded(source, segmenters, pipeline, stop)
                               : RunSequentially(source, *segmenters.front(), pipeline, stop);
    }
  } catch (const std::exception&) {
    // The frames taken before the error still go out (those waiting for a first scale or in
    // the back end's window).
    try {
      pipeline.Finish();
    } catch (const std::exception&) {
      // A second error (disk full) is not the one that stopped the run: that one is reported.
    }
    throw;
  }
  pipeline.Finish();
  result.summary.wall_s = MillisecondsSince(start) / 1000.0;
  result.summary.cpu_s = (ProcessCpuMs() - cpu_start) / 1000.0;
  return result;
}

}  // namespace roadscale
