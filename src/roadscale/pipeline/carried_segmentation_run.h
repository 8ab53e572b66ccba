#pragma once

#include <atomic>
#include <vector>

#include "roadscale/io/frame_source.h"
#include "roadscale/pipeline/run_pipeline.h"
#include "roadscale/pipeline/sequential_pipeline.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// RunPipeline's stages for SegmentationScheduleMode::kKeyframes: the frontend tracks each
// frame with masks carried from the last segmented frame whose result is due
// (FrontendMaskCarrier), the schedule then decides whether the network segments it; the
// network runs on its own threads beside the frontend, and the scale stage gets each frame's
// road mask fresh (segmented frames) or carried through the road homographies from the last
// segmented frame. Threaded: loading, frontend, the segmenters and the scale stage on their own
// threads; the poses are the same as without threads, byte for byte (frames.csv's time columns
// differ). Returns whether `stop`
// interrupted the run.
bool RunWithCarriedMasks(FrameSource& source, const std::vector<Segmenter*>& segmenters,
                         SequentialPipeline& pipeline, const PipelineOptions& options,
                         const RunPipelineOptions& run_options, const std::atomic<bool>* stop);

}  // namespace roadscale
