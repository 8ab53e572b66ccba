#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "roadscale/io/frame_source.h"
#include "roadscale/pipeline/scale_source.h"
#include "roadscale/pipeline/sequential_pipeline.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// Frames a queue between two stages holds; bounds the memory to a few images whatever the
// sequence's length. 2 lets a stage run ahead by one frame while the next is handed over.
inline constexpr size_t kStageQueueCapacity = 2;

struct RunPipelineOptions {
  // Run the three stages (1: image loading + segmentation, 2: frontend, 3: scale + pose +
  // writing) on their own threads (stage 1 on one per segmenter), connected by bounded queues, so
  // that their costs overlap (the paper runs the scale "as a separate thread alongside motion
  // estimation"). Each stage sees the frames in order and owns its state, so the output does not
  // depend on thread timing: the same input gives byte-identical poses with or without threads.
  bool threaded = true;
  // OpenCV's thread count (a process-wide setting) during the run; 0 leaves it. Changing it
  // while another thread runs an OpenCV parallel loop crashes OpenCV, so a run with a network
  // sets it here, before the threads start, to the network's dnn_threads: the segmenter then
  // finds it right and leaves it alone.
  int opencv_threads = 0;

  void Check() const;
};

// How a run ended.
struct PipelineRunResult {
  RunSummary summary;
  // True when `stop` was set: the frames read before it were processed and written.
  bool interrupted = false;
};

// The frame's name for segmenters that read precomputed labels: the image file's stem
// ("000042"), or the index as %06d for a video frame.
std::string FrameName(const Frame& frame);

// Runs every frame of `source` through segmentation and a SequentialPipeline, writing each
// finished frame to `out_dir` (RunOutputFiles: poses_kitti.txt, poses_tum.txt, frames.csv;
// an empty `out_dir` writes no files). `on_frame` is called with each frame and its pose
// after its rows are written, in order, from the scale and pose stage. `stop` (may be null) is read
// before each frame is loaded: once it is true no new frame is read, the frames already read are
// finished, and the result says `interrupted`. An error in any stage (a corrupt image, a
// missing label file) stops the run: the frames before it are finished and written, then
// the error is thrown. `on_provisional` gets each frame's provisional pose (ProvisionalPose)
// from the same stage, as soon as it is known.
PipelineRunResult RunPipeline(FrameSource& source, Segmenter& segmenter, ScaleSource& scale,
                              const PipelineOptions& options, const std::string& out_dir,
                              const RunPipelineOptions& run_options = {},
                              const FrameOutput& on_frame = {},
                              const std::atomic<bool>* stop = nullptr,
                              const ProvisionalOutput& on_provisional = {});

// The same with stage 1 on one thread per segmenter (interchangeable copies: each frame is
// segmented by one of them, whichever is free), the frames handed on in order; without
// threads the first segmenter does every frame.
PipelineRunResult RunPipeline(FrameSource& source, const std::vector<Segmenter*>& segmenters,
                              ScaleSource& scale, const PipelineOptions& options,
                              const std::string& out_dir,
                              const RunPipelineOptions& run_options = {},
                              const FrameOutput& on_frame = {},
                              const std::atomic<bool>* stop = nullptr,
                              const ProvisionalOutput& on_provisional = {});

}  // namespace roadscale
