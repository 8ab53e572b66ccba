#include "roadscale/pipeline/carried_segmentation_run.h"

#include <chrono>
#include <exception>
#include <memory>
#include <optional>

#include <opencv2/core.hpp>

#include "roadscale/pipeline/bounded_queue.h"
#include "roadscale/pipeline/frontend_mask_carrier.h"
#include "roadscale/pipeline/segmentation_schedule.h"
#include "roadscale/pipeline/segmentation_service.h"
#include "roadscale/pipeline/stage_thread.h"
#include "roadscale/segmentation/mask_carrying.h"
#include "roadscale/util/elapsed_time.h"

namespace roadscale {
namespace {

using Clock = std::chrono::steady_clock;

// A tracked frame with what the scale stage needs to complete its road mask.
struct CarriedFrame {
  TrackedFrame tracked;
  bool segmented = false;
  Eigen::Matrix3d road_step = Eigen::Matrix3d::Identity();  // cur_from_prev of the road
  // The frontend's carried moving-object mask of the frame when it holds the objects where
  // they were too (MaskCarryOptions::dynamic_in_place), else empty.
  cv::Mat dynamic_mask;
};

// The frontend stage: tracks with carried masks, then asks the schedule whether the network
// segments the frame.
class CarriedFrontend {
 public:
  CarriedFrontend(SequentialPipeline& pipeline, SegmentationService& service,
                  const PipelineOptions& options, const PinholeCamera& camera)
      : pipeline_(pipeline),
        service_(service),
        carrier_(options.segmentation_schedule.carry, options.segmentation_schedule.latency_frames,
                 camera.K()),
        schedule_(camera, options.segmentation_schedule.keyframes),
        carry_in_place_(options.segmentation_schedule.carry.dynamic_in_place),
        min_carried_road_share_(options.segmentation_schedule.min_carried_road_share) {}

  CarriedFrame Track(const SegmentedFrame& input) {
    const int index = static_cast<int>(input.frame.index);
    const bool first = !started_;
    started_ = true;
    if (first) service_.Submit(index, input.frame.image, FrameName(input.frame));
    const auto take = [&](int frame_index) { return service_.Take(frame_index).result; };
    CarriedFrame out;
    out.tracked = pipeline_.Track(input, [&](const std::vector<Correspondence>& correspondences) {
      return carrier_.Masks(index, correspondences, take);
    });
    carrier_.AddMotion(out.tracked.frontend.motion);
    out.road_step = carrier_.last_step();
    out.tracked.dynamic_mask = carrier_.last_dynamic_mask();
    if (carry_in_place_) out.dynamic_mask = carrier_.last_dynamic_mask();
    const bool road_shrunk =
        !carrier_.segmentation_pending() && carrier_.carried_road_share() < min_carried_road_share_;
    out.segmented = schedule_.Decide(out.tracked.frontend, carrier_.carry_failed() || road_shrunk);
    if (out.segmented && !first) {
      service_.Submit(index, input.frame.image, FrameName(input.frame));
      carrier_.AddSegmented(index);
    }
    return out;
  }

 private:
  SequentialPipeline& pipeline_;
  SegmentationService& service_;
  FrontendMaskCarrier carrier_;
  SegmentationSchedule schedule_;
  bool carry_in_place_;
  double min_carried_road_share_;
  bool started_ = false;
};

// The scale stage's road mask of each frame: a segmented frame's own, else the last segmented
// frame's carried through the road homographies since, less the frame's carried moving-object
// mask: a car that keeps pace with the camera stays where the carried road mask's hole for it
// has moved on, and points on its bumper would put the road too high and the steps too long.
class RoadMaskCompleter {
 public:
  explicit RoadMaskCompleter(SegmentationService& service) : service_(service) {}

  TrackedFrame Complete(CarriedFrame carried) {
    TrackedFrame& tracked = carried.tracked;
    FrameRecord& record = tracked.record;
    if (carried.segmented) {
      const ServedSegmentation served = service_.Take(static_cast<int>(record.index));
      record.segmented = served.result.HasLabels();
      record.segmentation_ms = served.result.milliseconds;
      record.segmentation_cpu_ms = served.cpu_ms;
      record.total_ms += served.result.milliseconds;
      road_ = served.result.road_mask;
      cur_from_road_.setIdentity();
      SetRoadMask(road_, &tracked);
      tracked.dynamic_mask = served.result.dynamic_mask;
    } else {
      cur_from_road_ = carried.road_step * cur_from_road_;
      cv::Mat road = CarryRoadMask(road_, cur_from_road_);
      if (!road.empty() && !carried.dynamic_mask.empty()) road.setTo(0, carried.dynamic_mask);
      SetRoadMask(road, &tracked);
    }
    return std::move(tracked);
  }

 private:
  SegmentationService& service_;
  cv::Mat road_;
  Eigen::Matrix3d cur_from_road_ = Eigen::Matrix3d::Identity();
};

bool LoadFrame(FrameSource& source, SegmentedFrame* out) {
  const Clock::time_point start = Clock::now();
  if (!source.Next(&out->frame)) return false;
  out->load_ms = MillisecondsSince(start);
  return true;
}

bool RunSequentially(FrameSource& source, CarriedFrontend& frontend, RoadMaskCompleter& roads,
                     SequentialPipeline& pipeline, const std::atomic<bool>* stop) {
  SegmentedFrame frame;
  while (true) {
    if (stop != nullptr && stop->load()) return true;
    if (!LoadFrame(source, &frame)) return false;
    pipeline.Integrate(roads.Complete(frontend.Track(frame)));
  }
}

bool RunThreaded(FrameSource& source, CarriedFrontend& frontend, RoadMaskCompleter& roads,
                 SequentialPipeline& pipeline, SegmentationService& service,
                 const PipelineOptions& options, const std::atomic<bool>* stop) {
  BoundedQueue<SegmentedFrame> loaded(kStageQueueCapacity);
  // Room for the frames the frontend runs ahead while the scale stage waits for a network.
  BoundedQueue<CarriedFrame> tracked(kStageQueueCapacity +
                                     options.segmentation_schedule.latency_frames);
  std::atomic<bool> interrupted{false};

  StageThread load_stage(
      [&] {
        while (true) {
          if (stop != nullptr && stop->load()) {
            interrupted = true;
            return;
          }
          SegmentedFrame frame;
          if (!LoadFrame(source, &frame) || !loaded.Push(std::move(frame))) return;
        }
      },
      [] {}, [&] { loaded.Close(); });
  const std::unique_ptr<StageThread> frontend_stage = StartQueueStage(
      loaded, tracked, [&](const SegmentedFrame& frame) { return frontend.Track(frame); });
  const std::exception_ptr integration_error = RunFinalStage(
      [&] {
        while (std::optional<CarriedFrame> frame = tracked.Pop()) {
          pipeline.Integrate(roads.Complete(std::move(*frame)));
        }
      },
      [&] {
        service.Cancel();
        tracked.Cancel();
        loaded.Cancel();
      });
  const std::exception_ptr frontend_error = frontend_stage->Join();
  const std::exception_ptr load_error = load_stage.Join();
  RethrowFirstError({integration_error, frontend_error, load_error});
  return interrupted.load();
}

}  // namespace

bool RunWithCarriedMasks(FrameSource& source, const std::vector<Segmenter*>& segmenters,
                         SequentialPipeline& pipeline, const PipelineOptions& options,
                         const RunPipelineOptions& run_options, const std::atomic<bool>* stop) {
  SegmentationService service(segmenters, run_options.threaded);
  CarriedFrontend frontend(pipeline, service, options, source.camera().camera);
  RoadMaskCompleter roads(service);
  return run_options.threaded
             ? RunThreaded(source, frontend, roads, pipeline, service, options, stop)
             : RunSequentially(source, frontend, roads, pipeline, stop);
}

}  // namespace roadscale
