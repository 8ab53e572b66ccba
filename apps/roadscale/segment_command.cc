// `roadscale segment`: runs a segmentation model over a KITTI sequence or an image folder and
// writes what it sees, for a person to check and for the pipeline to read back.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "roadscale/io/frame_source.h"
#include "roadscale/io/image_file.h"
#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/segmentation/make_segmenter.h"
#include "roadscale/util/error.h"

#include "commands.h"

namespace roadscale::cli {
namespace {

namespace fs = std::filesystem;

struct SegmentArguments {
  std::string kitti;
  std::string images;
  std::string camera;
  int kitti_camera = -1;
  std::string frames;
  std::string out;
  double overlay_weight = 0.5;
  // One network on the frames in turn: both cores go to its inference.
  SegmentationOptions segmentation = [] {
    SegmentationOptions options;
    options.dnn_threads = 2;
    return options;
  }();
};

void RunSegment(const SegmentArguments& arguments) {
  if (arguments.segmentation.model == "none") {
    throw Error(
        "--model none has no labels to write; give a model YAML such as "
        "config/models/espnetv2_512x256.yaml");
  }
  CheckOption(arguments.overlay_weight >= 0.0 && arguments.overlay_weight <= 1.0,
              "--overlay-weight", "must be in 0..1");

  FrameSourceOptions source_options;
  source_options.input = arguments.kitti.empty() ? arguments.images : arguments.kitti;
  source_options.camera_yaml = arguments.camera;
  source_options.kitti_camera = arguments.kitti_camera;
  // Colour when the input has it: the networks see far more in colour (docs/benchmark-history.md).
  source_options.color = true;
  source_options.frames = ParseFrameRange(arguments.frames);
  source_options.image_size_only = true;
  std::unique_ptr<ImageFileSequence> source;
  if (!arguments.kitti.empty()) {
    source = std::make_unique<KittiSequence>(source_options);
  } else {
    source = std::make_unique<ImageFolder>(source_options);
  }

  // Every check that can fail runs before the first frame: model, label files, output folder.
  std::unique_ptr<Segmenter> segmenter = MakeSegmenter(arguments.segmentation);
  std::vector<std::string> names;
  for (const std::string& path : source->image_paths()) {
    names.push_back(fs::path(path).stem().string());
  }
  const cv::Size image_size(source->camera().camera.width, source->camera().camera.height);
  segmenter->CheckFrames(names, image_size);

  const fs::path out(arguments.out);
  std::error_code error;
  fs::create_directories(out / "labels", error);
  fs::create_directories(out / "overlays", error);
  if (!fs::is_directory(out / "labels") || !fs::is_directory(out / "overlays")) {
    ThrowFileError(out.string(), "cannot create the output folder");
  }

  std::cout << "roadscale segment: " << source->Describe() << '\n'
            << "  model: " << segmenter->Description() << '\n';
  for (const std::string& note : source->notes()) std::cout << "  note: " << note << '\n';

  size_t frames = 0;
  size_t fresh = 0;
  double milliseconds = 0.0;
  const auto start = std::chrono::steady_clock::now();
  Frame frame;
  while (source->Next(&frame)) {
    const std::string name = fs::path(frame.path).stem().string();
    const SegmentationResult result = segmenter->Segment(frame.image, name);
    WriteImageFile(out / "labels" / (name + ".png"), result.labels);
    WriteImageFile(out / "overlays" / (name + ".png"),
                   OverlayTrainIds(frame.image, result.labels, arguments.overlay_weight));
    ++frames;
    if (result.fresh) {
      ++fresh;
      milliseconds += result.milliseconds;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // A model file for the label-image backend, so that the pipeline (or this command) can
  // read these labels back with --model OUT/labels.yaml.
  const fs::path labels_yaml = out / "labels.yaml";
  {
    std::ofstream yaml(labels_yaml);
    yaml << "# Written by roadscale segment with " << segmenter->Description() << "\n"
         << "backend: label_images\nfolder: labels\nids: train_ids\n";
    if (!yaml) ThrowFileError(labels_yaml.string(), "cannot write this file");
  }
  std::cout << std::fixed << std::setprecision(1) << "  " << frames << " frames (" << fresh
            << " segmented, " << (fresh > 0 ? milliseconds / fresh : 0.0)
            << " ms each on average), " << seconds << " s in all\n"
            << "  wrote " << (out / "labels").string() << "/*.png (Cityscapes train ids), "
            << (out / "overlays").string() << "/*.png, " << labels_yaml.string() << '\n';
}

}  // namespace

void RegisterSegmentCommand(CLI::App& app) {
  auto arguments = std::make_shared<SegmentArguments>();
  CLI::App* command = app.add_subcommand(
      "segment",
      "Run a semantic segmentation model over a sequence and write label images (Cityscapes "
      "train ids) and colour overlays, to check what the network sees; the labels can be fed "
      "back with --model OUT/labels.yaml.");
  CLI::Option* kitti = command->add_option("--kitti", arguments->kitti,
                                           "KITTI odometry sequence folder (.../sequences/NN)");
  CLI::Option* images = command->add_option(
      "--images", arguments->images, "folder of images (*.png, *.jpg), read in natural order");
  kitti->excludes(images);
  command->add_option("--camera", arguments->camera,
                      "camera YAML (Camera: block); optional: with --images the image size "
                      "comes from the first image, and a camera YAML checks it");
  command
      ->add_option("--kitti-camera", arguments->kitti_camera,
                   "KITTI camera 0..3 (image_N/); -1: image_0 when present, else image_2")
      ->capture_default_str();
  command
      ->add_option("--model", arguments->segmentation.model,
                   "segmentation model YAML, e.g. config/models/espnetv2_512x256.yaml "
                   "(see src/roadscale/segmentation/segmentation_model.h)")
      ->required();
  command->add_option("--out", arguments->out, "output folder (created)")->required();
  command->add_option("--frames", arguments->frames,
                      "frame range A:B (frames A..B-1); all if unset");
  command
      ->add_option("--every", arguments->segmentation.every,
                   "segment every K-th frame and reuse the last labels in between")
      ->capture_default_str();
  command
      ->add_option("--threads", arguments->segmentation.dnn_threads,
                   "threads OpenCV DNN uses for the network")
      ->capture_default_str();
  command
      ->add_option("--overlay-weight", arguments->overlay_weight,
                   "weight of the class colours blended over the image, 0..1")
      ->capture_default_str();
  command->callback([arguments, kitti, images]() {
    if (kitti->count() == 0 && images->count() == 0) {
      throw Error("roadscale segment needs --kitti SEQ_DIR or --images DIR");
    }
    RunSegment(*arguments);
  });
}

}  // namespace roadscale::cli
