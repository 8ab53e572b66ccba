#pragma once

#include <cstddef>
#include <vector>

namespace roadscale {

struct TimeAssociationOptions {
  // Largest accepted difference between associated timestamps, in seconds (evo's default
  // --t_max_diff, 0.01 s; KITTI frames are 0.1 s apart).
  double max_difference_s = 0.01;

  void Check() const;
};

// Index pairs (gt[k], est[k]) of associated poses.
struct TimeAssociation {
  std::vector<size_t> gt_indices;
  std::vector<size_t> est_indices;

  size_t size() const { return gt_indices.size(); }
};

// Associates two increasing timestamp lists as evo's `associate_trajectories` does: every
// timestamp of the shorter list (the estimate's when both are as long) is paired with
// the nearest timestamp of the other list (the earlier one on a tie) when they differ by
// at most max_difference_s; timestamps without such a partner are dropped. As in evo, one
// timestamp of the longer list can be the partner of two, which happens only when two
// timestamps of the shorter list lie within 2 max_difference_s of each other. Pairs come in
// increasing time. Throws Error when a list is not strictly increasing.
TimeAssociation AssociateByTime(const std::vector<double>& gt_timestamps,
                                const std::vector<double>& est_timestamps,
                                const TimeAssociationOptions& options = {});

}  // namespace roadscale
