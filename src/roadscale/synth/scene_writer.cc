#include "roadscale/synth/scene_writer.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include <opencv2/imgproc.hpp>
#include <unistd.h>

#include "roadscale/io/camera_setup.h"
#include "roadscale/io/image_file.h"
#include "roadscale/io/image_undistorter.h"
#include "roadscale/io/kitti_calib.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/synth/network_like_labels.h"
#include "roadscale/synth/road_plane_file.h"
#include "roadscale/util/error.h"

namespace roadscale::synth {
namespace {

namespace fs = std::filesystem;

void MakeDirectory(const fs::path& path) {
  std::error_code error;
  fs::create_directories(path, error);
  if (error) ThrowFileError(path.string(), "cannot create folder: " + error.message());
}

std::string FrameName(int index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06d.png", index);
  return name;
}

class TextFile {
 public:
  explicit TextFile(const fs::path& path) : path_(path.string()), file_(path_) {
    if (!file_) ThrowFileError(path_, "cannot open for writing");
  }
  std::ofstream& stream() { return file_; }
  void Close() {
    file_.flush();
    if (!file_) ThrowFileError(path_, "write failed");
    file_.close();
  }

 private:
  std::string path_;
  std::ofstream file_;
};

}  // namespace

void CheckSequenceName(const std::string& sequence) {
  bool ok = !sequence.empty() && sequence.size() <= 8;
  for (const char c : sequence) ok = ok && c >= '0' && c <= '9';
  if (!ok) throw Error("invalid sequence name '" + sequence + "' (expected digits such as 00)");
}

void WriteSyntheticSequence(SyntheticScene& scene, const SceneWriterOptions& options) {
  CheckSequenceName(options.sequence);
  if (options.max_frames < 0) throw Error("max_frames must be >= 0 (0: every frame)");
  const SceneOptions& scene_options = scene.options();
  CameraSetup setup;
  setup.camera = scene_options.image.camera;
  setup.h0 = scene_options.vehicle.h0;
  setup.distortion = options.distortion;
  setup.Check();  // a lens no camera.yaml can hold is refused before any file is made
  const fs::path root(options.out_dir);
  const fs::path sequence = root / "sequences" / options.sequence;
  for (const char* folder : {"image_0", "semantic", "depth", "moving"}) {
    MakeDirectory(sequence / folder);
  }
  if (options.colour) MakeDirectory(sequence / "image_2");
  std::optional<NetworkLikeLabels> network_labels;
  if (scene.options().labels.Any()) {
    MakeDirectory(sequence / "semantic_network");
    network_labels.emplace(scene.options().labels, scene.options().seed);
  }
  MakeDirectory(root / "poses");

  WriteKittiCalib((sequence / "calib.txt").string(), scene_options.image.camera);
  WriteCameraYaml((sequence / "camera.yaml").string(), setup);
  std::optional<ImageDistorter> lens;
  if (!options.distortion.empty()) lens.emplace(setup.camera, options.distortion);
  const auto through_lens = [&lens](const cv::Mat& image) {
    return lens ? lens->Distort(image, cv::INTER_LINEAR) : image;
  };

  TextFile times(sequence / "times.txt");
  TextFile planes(sequence / "road_planes.txt");
  planes.stream() << RoadPlaneFileHeader() << '\n';
  Trajectory trajectory;
  const bool tty = options.progress && isatty(2);
  const int frames =
      options.max_frames > 0 ? std::min(options.max_frames, scene.frames()) : scene.frames();
  for (int i = 0; i < frames; ++i) {
    const SynthFrame frame = scene.Render(i, options.colour);
    const std::string name = FrameName(i);
    WriteImageFile(sequence / "image_0" / name, through_lens(frame.images.grey));
    if (options.colour)
      WriteImageFile(sequence / "image_2" / name, through_lens(frame.images.colour));
    WriteImageFile(sequence / "semantic" / name, frame.images.labels);
    if (network_labels) {
      WriteImageFile(sequence / "semantic_network" / name,
                     network_labels->Next(frame.images.labels));
    }
    WriteImageFile(sequence / "depth" / name, frame.images.depth);
    WriteImageFile(sequence / "moving" / name, frame.images.moving);
    char line[160];
    std::snprintf(line, sizeof(line), "%e\n", frame.time);
    times.stream() << line;
    planes.stream() << FormatRoadPlaneRow({i, frame.road_plane.normal, frame.road_plane.height})
                    << '\n';
    trajectory.world_from_cam.push_back(frame.world_from_cam);
    trajectory.timestamps.push_back(frame.time);
    if (tty) {
      std::fprintf(stderr, "\rroadscale synth: frame %d / %d", i + 1, frames);
      std::fflush(stderr);
    }
  }
  if (tty) std::fprintf(stderr, "\n");
  times.Close();
  planes.Close();
  WriteKittiTrajectory((root / "poses" / (options.sequence + ".txt")).string(), trajectory);
}

}  // namespace roadscale::synth
