#include "roadscale/eval/pose_pairing.h"

#include <sstream>

#include "roadscale/util/error.h"

namespace roadscale {

PosePairs PairPoses(const Trajectory& gt, const Trajectory& est, const std::string& gt_name,
                    const std::string& est_name, const TimeAssociationOptions& options) {
  PosePairs pairs;
  if (gt.HasTimestamps() && est.HasTimestamps()) {
    const TimeAssociation association = AssociateByTime(gt.timestamps, est.timestamps, options);
    if (association.size() < 2) {
      std::ostringstream message;
      message << "associating " << est_name << " (" << est.size() << " poses) with " << gt_name
              << " (" << gt.size() << " poses) by time found " << association.size()
              << " pair(s) with timestamps within " << options.max_difference_s
              << " s of each other; evaluation needs at least 2 (are both on the same clock?)";
      throw Error(message.str());
    }
    pairs.by_time = true;
    for (size_t k = 0; k < association.size(); ++k) {
      pairs.gt_world_from_cam.push_back(gt.world_from_cam[association.gt_indices[k]]);
      pairs.est_world_from_cam.push_back(est.world_from_cam[association.est_indices[k]]);
    }
    return pairs;
  }

  if (gt.size() != est.size()) {
    throw Error(est_name + " has " + std::to_string(est.size()) + " poses but " + gt_name +
                " has " + std::to_string(gt.size()) +
                ": without timestamps on both, pose i is compared with pose i, so the counts "
                "must match (a TUM estimate is associated by time when the ground truth has "
                "timestamps too: a TUM file, or KITTI poses with --times)");
  }
  if (gt.size() < 2) {
    throw Error(gt_name + " has " + std::to_string(gt.size()) +
                " pose(s); evaluation needs at least 2");
  }
  pairs.gt_world_from_cam = gt.world_from_cam;
  pairs.est_world_from_cam = est.world_from_cam;
  return pairs;
}

}  // namespace roadscale
