// roadscale in a program of its own, built against the installed package: the first FRAMES
// frames of a KITTI odometry sequence through roadscale::Odometry, each metric pose printed
// as a KITTI row (12 numbers, row-major 3x4 world_from_cam), as `roadscale run` writes
// poses_kitti.txt: with the same options the rows are the same, to the byte.
//
// Usage: cpp_odometry SEQUENCE_DIR FRAMES [MODEL_YAML]
//   SEQUENCE_DIR  a KITTI sequence folder (.../sequences/NN: image_0/, calib.txt, times.txt)
//   FRAMES        how many frames from the first
//   MODEL_YAML    a segmentation model (PREFIX/share/roadscale/config/models/); none without it
#include <iostream>
#include <memory>
#include <string>

#include "roadscale/config/config_yaml.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/odometry/odometry.h"
#include "roadscale/odometry/odometry_config.h"
#include "roadscale/util/error.h"

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: cpp_odometry SEQUENCE_DIR FRAMES [MODEL_YAML]\n";
    return 1;
  }
  try {
    // The library reads the frames here; a program with a camera of its own would hand its
    // images to Track as they come.
    roadscale::FrameSourceOptions input;
    input.type = roadscale::FrameSourceType::kKitti;
    input.input = argv[1];
    input.frames = roadscale::ParseFrameRange(std::string(":") + argv[2]);  // run's --frames :N
    const std::unique_ptr<roadscale::FrameSource> frames = roadscale::OpenFrameSource(input);
    for (const std::string& note : frames->notes()) std::cerr << "note: " << note << '\n';

    // `roadscale run`'s defaults (config/kitti.yaml's values), calib.txt's camera.
    roadscale::RunConfig config;
    config.segmentation.model = argc > 3 ? argv[3] : "none";
    const auto segmenters = roadscale::MakeConfigSegmenters(config);
    roadscale::Odometry odometry(
        roadscale::OdometryOptionsFromConfig(config, frames->camera()),
        roadscale::Pointers(segmenters),
        // On the odometry's thread, once a frame's pose is final, in frame order.
        [](const roadscale::FrameRecord&, const roadscale::Rigid3d& world_from_cam) {
          std::cout << roadscale::FormatKittiRow(world_from_cam) << '\n';
        });
    roadscale::Frame frame;
    while (frames->Next(&frame)) odometry.Track(frame.image, frame.timestamp, frame.path);
    std::cerr << odometry.Finish().summary.Format();
  } catch (const roadscale::Error& error) {
    std::cerr << "cpp_odometry: error: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
