// `roadscale run`: the visual odometry on a sequence, writing OUT/poses_kitti.txt while it
// runs. For now the sequential pipeline without segmentation; the scale from the road plane
// (the paper's method, the default) or from the ground truth (oracle).
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "roadscale/frontend/feature_detector.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/pipeline/oracle_scale_source.h"
#include "roadscale/pipeline/road_scale_source.h"
#include "roadscale/pipeline/sequential_pipeline.h"
#include "roadscale/util/error.h"

#include "commands.h"

namespace roadscale::cli {
namespace {

struct RunArguments {
  std::string kitti;
  std::string scale = "road";
  std::optional<double> h0;
  bool no_segmentation = false;
  std::string detector = "sift";
  std::string frames;
  std::string out;
};

void RunRun(const RunArguments& arguments) {
  PipelineOptions options;
  options.frontend.tracker.detector.type = ParseDetectorType(arguments.detector);
  options.Check();
  if (arguments.scale != "oracle" && arguments.scale != "road") {
    throw Error("unknown --scale '" + arguments.scale + "' (expected road or oracle)");
  }

  FrameSourceOptions source_options;
  source_options.input = arguments.kitti;
  source_options.type = FrameSourceType::kKitti;
  source_options.frames = ParseFrameRange(arguments.frames);
  source_options.h0 = arguments.h0;
  const std::unique_ptr<FrameSource> source = OpenFrameSource(source_options);
  for (const std::string& note : source->notes()) std::cerr << "roadscale: note: " << note << '\n';

  const Trajectory* ground_truth = source->ground_truth();
  std::unique_ptr<ScaleSource> scale_source;
  if (arguments.scale == "oracle") {
    if (ground_truth == nullptr) {
      throw Error(arguments.kitti +
                  ": --scale oracle needs ground-truth poses (../../poses/NN.txt beside the "
                  "sequence folder), and there are none");
    }
    scale_source = std::make_unique<OracleScaleSource>(*ground_truth);
  } else {
    ScaleEstimatorOptions scale_options;
    scale_options.camera_height = source->camera().h0;
    scale_source = std::make_unique<RoadScaleSource>(source->camera().camera, scale_options);
  }
  ScaleSource& scale = *scale_source;

  std::cout << "Input:  " << source->Describe() << '\n'
            << "Scale:  " << scale.Name()
            << (arguments.scale == "road" ? " (h0 = " + std::to_string(source->camera().h0) + " m)"
                                          : std::string())
            << '\n'
            << "Frontend: " << arguments.detector << " features, no segmentation\n";
  const RunSummary summary = RunSequentialPipeline(*source, scale, options, arguments.out);
  // The ground truth of the same frames beside the estimate, so that `roadscale eval` can
  // compare them pose for pose.
  std::cout << summary.Format() << "Poses:  " << arguments.out << "/poses_kitti.txt\n"
            << "Frames: " << arguments.out << "/frames.csv\n";
  if (ground_truth != nullptr) {
    const std::string gt_path = arguments.out + "/gt_poses_kitti.txt";
    WriteKittiTrajectory(gt_path, *ground_truth);
    std::cout << "Ground truth of these frames: " << gt_path << '\n';
  }
}

}  // namespace

void RegisterRunCommand(CLI::App& app) {
  auto arguments = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand(
      "run",
      "Run the monocular visual odometry on a sequence and write OUT/poses_kitti.txt (one "
      "world_from_cam row per input frame, the first frame is the world; written and flushed "
      "frame by frame) and OUT/frames.csv (per-frame status, counts and stage times in ms).");
  command
      ->add_option("--kitti", arguments->kitti, "KITTI odometry sequence folder (.../sequences/NN)")
      ->required();
  command
      ->add_option("--scale", arguments->scale,
                   "Where each step's length comes from: road = the road plane and the camera "
                   "height h0 (the paper's method; per-frame diagnostics in frames.csv), "
                   "oracle = the ground truth's step length (needs .../poses/NN.txt; isolates "
                   "the frontend's error)")
      ->capture_default_str();
  command->add_option("--h0", arguments->h0,
                      "Camera height above the road in metres (default: the sequence's "
                      "camera.yaml, else KITTI's 1.65)");
  command->add_flag("--no-segmentation", arguments->no_segmentation,
                    "Run without semantic segmentation (features on the whole image). The only "
                    "mode for now: the flag is accepted and changes nothing (default: on)");
  command
      ->add_option("--detector", arguments->detector,
                   "Feature detector: sift (the paper's), orb, brisk, akaze or fast")
      ->capture_default_str();
  command->add_option("--frames", arguments->frames,
                      "Frames to process: A:B (A..B-1), A: or :B (default: all)");
  command->add_option("--out", arguments->out, "Output folder (created when missing)")->required();
  command->callback([arguments] { RunRun(*arguments); });
}

}  // namespace roadscale::cli
