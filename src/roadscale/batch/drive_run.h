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
// (so a batch folder can be moved) and the contents of its config, camera and model files
// (editing a config reruns the drive). Folders of frames or label images are
// taken by path only: hashing gigabytes of images at every resume would cost more than it
// saves. Throws Error when one of those files cannot be read.
std::string DriveFingerprint(const BatchDrive& drive, const std::string& roadscale_version);

}  // namespace roadscale::batch
