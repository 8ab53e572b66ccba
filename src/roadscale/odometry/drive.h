#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "roadscale/config/config_yaml.h"
#include "roadscale/eval/trajectory_evaluation.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/odometry/odometry.h"
#include "roadscale/odometry/odometry_config.h"
#include "roadscale/pipeline/run_pipeline.h"
#include "roadscale/pipeline/scale_source.h"
#include "roadscale/segmentation/segmenter.h"

namespace roadscale {

// What one drive is run from: its frames, every option, and the folder it writes to.
struct DriveSetup {
  // Input, its type, the frames, the camera YAML. Without a camera YAML an image folder or a
  // video takes the config's Camera block (written to OUT/camera.yaml).
  FrameSourceOptions source;
  // Every option; Camera.h0 replaces the camera's when set; Segmentation.model must name a
  // model YAML or "none" (ResolveDefaultModel turns "default" into one of them).
  RunConfig config;
  std::string out_dir;
  // Where the config came from, for the report ("defaults" when empty).
  std::string config_name;
};

// One drive as `roadscale run` runs it: the frames read from files or a video, segmented, run
// through the pipeline into OUT's rows, then the report and, with ground truth, the metrics.
class Drive {
 public:
  // Opens the input and checks what can fail before the first frame (the camera, every
  // segmenter against the frames' names and size, the scale source: oracle needs ground
  // truth), then writes OUT/config_used.yaml (the options as used: the camera's, the model's).
  // Throws Error naming the file or option.
  explicit Drive(DriveSetup setup);
  ~Drive();

  // Lines for the user before the first frame: the input, scale, mapping, frontend and
  // segmentation; and what the input wants said (FrameSource::notes).
  std::string Describe() const;
  std::vector<std::string> notes() const { return source_->notes(); }
  // Frames in the input (a video's as its container says).
  size_t size() const { return source_->size(); }

  // Runs every frame (segmentation, frontend and scale and pose on their own threads when
  // `threaded`), writing OUT/poses_kitti.txt, poses_tum.txt and frames.csv as frames finish;
  // `on_frame` after each. `stop` as RunPipeline's. Throws the error that stopped the run after
  // the frames before it are written.
  PipelineRunResult Run(bool threaded, const FrameOutput& on_frame = {},
                        const std::atomic<bool>* stop = nullptr);

  struct Report {
    std::optional<TrajectoryEvaluation> evaluation;  // with ground truth
    std::vector<std::string> written;                // the files written
    bool ground_truth_written = false;               // OUT/gt_poses_kitti.txt
    std::vector<std::string> warnings;               // about the scale (ScaleWarnings)
  };
  // After Run: OUT/report.html titled `title` (default: "roadscale run: " and the input),
  // and with ground truth OUT/gt_poses_kitti.txt and metrics.json, from the frames Run gave.
  Report WriteReport(const std::string& title) const;

 private:
  DriveSetup setup_;
  std::unique_ptr<FrameSource> source_;
  std::vector<std::unique_ptr<Segmenter>> owned_segmenters_;
  NoSegmenter no_segmentation_;
  std::vector<Segmenter*> segmenters_;
  std::unique_ptr<ScaleSource> scale_source_;
  OdometryOptions odometry_;
  std::string segmentation_text_;
  PipelineRunResult result_;
  std::vector<FrameRecord> records_;
  std::vector<Rigid3d> world_from_cam_;
};

}  // namespace roadscale
