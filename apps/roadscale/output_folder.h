#pragma once

#include <string>

namespace roadscale::cli {

// An output folder holds one run: `run` and `rescale` call this before writing anything,
// after reading their inputs (a --config OUT/config_used.yaml or --trajectory
// OUT/poses_kitti.txt of the previous run is read by then). It creates `out` when missing and
// removes the files either command writes (poses_kitti.txt, poses_tum.txt, frames.csv,
// config_used.yaml, report.html, metrics.json, gt_poses_kitti.txt, rescale.csv), so that a run
// that fails part way never leaves an earlier run's report or metrics beside its own shorter
// poses. Nothing else in the folder is touched. Throws Error naming the folder or the file
// that cannot be created or removed.
void PrepareOutputFolder(const std::string& out);

}  // namespace roadscale::cli
