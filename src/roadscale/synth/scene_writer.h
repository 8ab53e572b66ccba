#pragma once

#include <string>
#include <vector>

#include "roadscale/synth/synthetic_scene.h"

namespace roadscale::synth {

struct SceneWriterOptions {
  std::string out_dir;          // the dataset root (KITTI layout below it)
  std::string sequence = "00";  // sequence folder name
  bool colour = false;          // also write image_2 (BGR)
  bool progress = false;        // print progress to stderr
  // Writes only the scene's first `max_frames` frames (0: all). A scene's road and traffic
  // are laid out for its whole length, so the beginning of a long drive is not the same as a
  // short drive: this renders the one without the cost of the rest.
  int max_frames = 0;
  // A lens's distortion (OpenCV's model, 5 or 8 coefficients; empty: none). The frames
  // (image_0, image_2) are written as that lens shows them and camera.yaml carries the
  // coefficients; calib.txt keeps the pinhole camera that the frame sources undistort the
  // frames to, and the ground truth images (semantic, depth, moving) stay in that pinhole
  // geometry: they describe the frames as the pipeline sees them (--labels works as it is).
  // The renderer draws the pinhole field of view only, so a barrel lens's wider view shows
  // black beyond it; undistorting never reaches there.
  std::vector<double> distortion;
};

// Renders the frames of `scene` (SceneWriterOptions::max_frames) and writes, below out_dir:
//   sequences/NN/image_0/%06d.png   grey frames
//   sequences/NN/image_2/%06d.png   colour frames (with `colour`)
//   sequences/NN/semantic/%06d.png  Cityscapes train ids (8 bit)
//   sequences/NN/depth/%06d.png     z depth, 16 bit, 1/256 m, 0 = none (sky, > 256 m)
//   sequences/NN/moving/%06d.png    255 on objects moving in the world at that frame, else 0
//   sequences/NN/calib.txt, times.txt, camera.yaml (intrinsics and h0)
//   sequences/NN/road_planes.txt    "frame nx ny nz h" (camera frame, n . X = h)
//   poses/NN.txt                    world_from_cam, frame 0 = identity
// Throws Error naming the file that could not be written.
void WriteSyntheticSequence(SyntheticScene& scene, const SceneWriterOptions& options);

// "NN" check: one or more digits, as KITTI's sequence folders.
void CheckSequenceName(const std::string& sequence);

}  // namespace roadscale::synth
