#pragma once

#include <cstddef>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/io/frame_source.h"
#include "roadscale/odometry/pushed_frames.h"
#include "roadscale/pipeline/run_pipeline.h"
#include "roadscale/pipeline/scale_source.h"
#include "roadscale/pipeline/sequential_pipeline.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

struct OdometryOptions {
  // Intrinsics, image size and h0, the camera's height above the road: it is the road
  // scale's camera height (it replaces pipeline.road_selection.camera_height).
  CameraSetup camera;
  // Everything of the system: frontend, keyframe back end, road selection, segmentation
  // schedule (config/kitti.yaml lists them; ReadRunConfig reads them).
  PipelineOptions pipeline;
  // Threads (the default: segmentation, frontend, scale and pose each on their own) and
  // OpenCV's thread count during the run.
  RunPipelineOptions run;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// roadscale as a library: monocular images in, metric poses out, no files. What `roadscale
// run` does with a folder of images, for a program that has its frames in memory (a camera
// driver, a ROS node, a notebook):
//
//   Odometry odometry(options, {&network}, [&](const FrameRecord& record,
//                                              const Rigid3d& world_from_cam) { ... });
//   for (each image) odometry.Track(image, timestamp);
//   odometry.Finish();
//
// Each frame reaches `output` once its pose is final, in frame order: in the keyframe back
// end when its keyframe interval leaves the bundle-adjusted window (10 keyframes, about 1-3
// s of driving behind the newest frame), before the first scale when that scale is found.
// The poses are the same, to the byte, as `roadscale run` writes for the same frames and
// options. The work runs on the odometry's own threads; `output` is called on one of them.
class Odometry {
 public:
  // `segmenters`: the road and moving-object masks (a network, or label images found by the
  // frame's name), not owned, alive until Finish; several are interchangeable copies that
  // segment frames at once; none: no segmentation (the paper's ablation). `scale`: the step
  // lengths of the frame-to-frame host (not owned; nullptr: the road plane of section III);
  // the keyframe back end makes its own. `provisional`: each frame's provisional pose as soon
  // as the odometry has taken the frame (ProvisionalPose: the map's localisation, refined
  // before `output` gives the final pose a window later), in frame order, from the same
  // thread as `output`. Throws Error on invalid options.
  Odometry(const OdometryOptions& options, std::vector<Segmenter*> segmenters, FrameOutput output,
           ScaleSource* scale = nullptr, ProvisionalOutput provisional = {});
  // Waits for the frames handed in so far to be processed, without Finish's errors.
  ~Odometry();
  Odometry(const Odometry&) = delete;
  Odometry& operator=(const Odometry&) = delete;

  // Hands in the next frame: `image` grey (CV_8UC1) or BGR (CV_8UC3) of the camera's size,
  // copied; `timestamp` in seconds, increasing; `name` the image's file name or path when a
  // label segmenter reads <stem>.png for it (else the frame's number is its name). Returns
  // once the frame is queued: waits while the odometry is two frames behind. Throws Error on
  // a bad image or timestamp (the frame is not taken, the run goes on), and the error that
  // stopped the odometry when it has stopped (after which it takes no frame).
  void Track(const cv::Mat& image, double timestamp, const std::string& name = "");

  // Processes the frames still queued, hands every frame still waiting to `output` (those
  // in the back end's window, or waiting for a first scale: unscaled), and returns the run's
  // summary. Throws the error that stopped the odometry, if one did; the frames before it
  // have reached `output`. A second call returns the same.
  PipelineRunResult Finish();

 private:
  void Run();
  // Ends the input and waits for the odometry's thread.
  void Stop();

  OdometryOptions options_;
  FrameOutput output_;
  ProvisionalOutput provisional_;
  NoSegmenter no_segmenter_;
  std::vector<Segmenter*> segmenters_;
  std::unique_ptr<ScaleSource> road_scale_;
  ScaleSource* scale_ = nullptr;
  PushedFrames frames_;
  size_t next_index_ = 0;
  double last_timestamp_ = 0.0;
  bool stopped_ = false;
  PipelineRunResult result_;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace roadscale
