#pragma once

#include <string>
#include <vector>

#include "roadscale/batch/manifest.h"

namespace roadscale::batch {

// `roadscale run`'s arguments for a drive's run (without the program name): "run", then its
// options in a fixed order, then "--out" `out_dir`. Running them is the drive.
std::vector<std::string> RunArguments(const RunRequest& run, const std::string& out_dir);

// What decides a drive's outputs, as 16 hex digits (64-bit FNV-1a): the version of the
// roadscale that runs it (a new version reruns every drive), its run arguments without --out
// (so a batch folder can be moved), the contents of its config and camera files (editing a
// config reruns the drive) and of the segmentation model its run loads, YAML and ONNX weights
// (DriveModelFile; new weights under the same name rerun it). Folders of frames or label
// images are taken by path only: hashing gigabytes of images at every resume would cost more
// than it saves. Throws Error when one of those files cannot be read, except the default
// model, whose absence run answers by running without segmentation.
std::string DriveFingerprint(const BatchDrive& drive, const std::string& roadscale_version,
                             const std::string& default_model);

// The segmentation model YAML a drive's run loads, chosen as run chooses it: none (empty)
// with label images or without segmentation, given as a drive key or in its config; else the
// drive's model, else its config's Segmentation.model, else `default_model`.
std::string DriveModelFile(const BatchDrive& drive, const std::string& default_model);

}  // namespace roadscale::batch
