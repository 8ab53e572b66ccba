#pragma once

#include <string>

#include "roadscale/util/folder_lock.h"

namespace roadscale::cli {

// An output folder holds one run: `run` and `rescale` call this before writing anything,
// after reading their inputs (a --config OUT/config_used.yaml or --trajectory
// OUT/poses_kitti.txt of the previous run is read by then). It creates `out` when missing and
// removes the files either command writes (poses_kitti.txt, poses_tum.txt, frames.csv,
// config_used.yaml, report.html, metrics.json, gt_poses_kitti.txt, rescale.csv), so that a run
// that fails part way never leaves an earlier run's report or metrics beside its own shorter
// poses. Nothing else in the folder is touched. Before removing anything it locks the folder
// for `command` (FolderLock): hold the returned lock until the last output is written. Throws
// Error naming the folder or the file that cannot be created, locked or removed, and naming the
// holder when another process writes into the folder.
[[nodiscard]] FolderLock PrepareOutputFolder(const std::string& out, const std::string& command);

}  // namespace roadscale::cli
