#pragma once

#include <string>
#include <vector>

#include "roadscale/pipeline/run_request.h"

namespace roadscale::batch {

// One drive of a batch: the run `roadscale run` makes of it, with every path absolute, and
// its name (the folder DIR/<name>/ of its outputs).
struct BatchDrive : RunRequest {
  std::string name;
};

// The drives of a batch, in the order given.
struct BatchManifest {
  std::vector<BatchDrive> drives;
};

// Reads a manifest:
//   drives:
//     - name: kitti00
//       kitti: /data/kitti/sequences/00
//       frames: "0:2000"
//     - name: commute
//       video: commute.mp4          # relative paths are relative to the manifest's folder
//       camera: dashcam.yaml
// A drive's keys are run's options (kitti, images, video, camera, config, model, labels,
// no_segmentation, scale, detector, h0, frames, sequential). Throws Error naming the manifest
// and the line on an unknown key, a drive without exactly one input, an input, camera,
// config, model or labels path that does not exist, a value run would refuse (frames, scale,
// detector, h0), a name that is not a plain folder name, and a name given twice.
BatchManifest ReadBatchManifest(const std::string& path);

// The drives of KITTI odometry sequences under `root` (the folder holding sequences/ and
// poses/): one drive per sequence, named after it ("00"), reading ROOT/sequences/NN as
// `run --kitti` does. `sequences` as ParseSequenceList takes it. Throws Error naming a
// sequence folder that does not exist.
BatchManifest KittiBatchManifest(const std::string& root, const std::string& sequences);

// "00-10" -> 00, 01, ..., 10; "00,02,05-07" -> 00, 02, 05, 06, 07. Names keep the width of
// what was written ("0-2" -> 0, 1, 2). Throws Error on anything else, a range that runs
// backwards and a sequence listed twice.
std::vector<std::string> ParseSequenceList(const std::string& text);

// Throws Error(what + ": ...") unless `name` can be a drive's folder: letters, digits, '.',
// '_' and '-', not starting with '.', at most 100 characters, and none of the batch's own
// names (in any case): "slurm" (the folder of the Slurm scripts), "batch.json" and
// "summary.{md,csv,json,html}".
void CheckDriveName(const std::string& name, const std::string& what);

}  // namespace roadscale::batch
