#pragma once

#include <string>
#include <vector>

#include "roadscale/eval/time_association.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/io/trajectory_io.h"

namespace roadscale {

// Ground-truth and estimated poses paired one to one, ready for evaluation.
struct PosePairs {
  std::vector<Rigid3d> gt_world_from_cam;
  std::vector<Rigid3d> est_world_from_cam;
  bool by_time = false;  // associated by timestamps (else pose i with pose i)

  size_t size() const { return gt_world_from_cam.size(); }
};

// When both trajectories have timestamps, associates them by time (AssociateByTime);
// otherwise pairs pose i with pose i, which needs the same number of poses. The names
// (file paths) are for the messages. Throws Error when the counts differ without
// timestamps, or when fewer than 2 pairs result.
PosePairs PairPoses(const Trajectory& gt, const Trajectory& est, const std::string& gt_name,
                    const std::string& est_name, const TimeAssociationOptions& options = {});

}  // namespace roadscale
