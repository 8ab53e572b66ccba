#include "roadscale/odometry/odometry.h"

#include <cmath>
#include <utility>

#include "roadscale/pipeline/road_scale_source.h"
#include "roadscale/util/error.h"

namespace roadscale {

void OdometryOptions::Check() const {
  camera.camera.Check();
  CheckOption(std::isfinite(camera.h0) && camera.h0 > 0.0, "camera.h0",
              "must be > 0 (the camera's height above the road, metres)");
  pipeline.Check();
  run.Check();
}

Odometry::Odometry(const OdometryOptions& options, std::vector<Segmenter*> segmenters,
                   FrameOutput output, ScaleSource* scale, ProvisionalOutput provisional)
    : options_(options),
      output_(std::move(output)),
      provisional_(std::move(provisional)),
      segmenters_(std::move(segmenters)),
      scale_(scale),
      frames_(options.camera, kStageQueueCapacity) {
  options_.pipeline.road_selection.camera_height = options_.camera.h0;
  options_.Check();
  for (const Segmenter* segmenter : segmenters_) {
    CheckOption(segmenter != nullptr, "segmenters", "a segmenter is null");
  }
  if (segmenters_.empty()) segmenters_.push_back(&no_segmenter_);
  if (scale_ == nullptr) {
    road_scale_ =
        std::make_unique<RoadScaleSource>(options_.camera.camera, options_.pipeline.road_selection);
    scale_ = road_scale_.get();
  }
  thread_ = std::thread([this] { Run(); });
}

Odometry::~Odometry() { Stop(); }

void Odometry::Run() {
  try {
    result_ = RunPipeline(frames_, segmenters_, *scale_, options_.pipeline, /*out_dir=*/"",
                          options_.run, output_, /*stop=*/nullptr, provisional_);
  } catch (...) {
    error_ = std::current_exception();
  }
  // A Track waiting for room returns now; frames not taken are dropped.
  frames_.Cancel();
}

void Odometry::Track(const cv::Mat& image, double timestamp, const std::string& name) {
  const std::string frame = "frame " + std::to_string(next_index_);
  if (stopped_) {
    if (error_) std::rethrow_exception(error_);
    throw Error(frame + ": the odometry has finished and takes no more frames");
  }
  const PinholeCamera& camera = options_.camera.camera;
  if (image.empty() || (image.type() != CV_8UC1 && image.type() != CV_8UC3)) {
    throw Error(frame + ": the image must be 8-bit grey or BGR (" +
                (image.empty() ? std::string("empty") : "type " + std::to_string(image.type())) +
                ")");
  }
  if (image.cols != camera.width || image.rows != camera.height) {
    throw Error(frame + ": the image is " + std::to_string(image.cols) + "x" +
                std::to_string(image.rows) + ", the camera's " + std::to_string(camera.width) +
                "x" + std::to_string(camera.height));
  }
  if (!std::isfinite(timestamp) || (next_index_ > 0 && timestamp <= last_timestamp_)) {
    throw Error(frame + ": timestamp " + std::to_string(timestamp) +
                " s does not come after the previous frame's (" + std::to_string(last_timestamp_) +
                " s)");
  }
  Frame pushed;
  pushed.index = next_index_;
  pushed.timestamp = timestamp;
  pushed.image = image.clone();
  pushed.path = name;
  if (!frames_.Push(std::move(pushed))) {
    Stop();
    if (error_) std::rethrow_exception(error_);
    throw Error(frame + ": the odometry has stopped");
  }
  ++next_index_;
  last_timestamp_ = timestamp;
}

PipelineRunResult Odometry::Finish() {
  Stop();
  if (error_) std::rethrow_exception(error_);
  return result_;
}

void Odometry::Stop() {
  if (stopped_) return;
  stopped_ = true;
  frames_.Close();
  thread_.join();
}

}  // namespace roadscale
