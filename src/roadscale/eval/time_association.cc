#include "roadscale/eval/time_association.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

void CheckIncreasing(const std::vector<double>& timestamps, const char* which) {
  for (size_t i = 1; i < timestamps.size(); ++i) {
    if (!(timestamps[i] > timestamps[i - 1])) {
      throw Error(std::string("time association: the ") + which +
                  " timestamps must increase, but timestamp " + std::to_string(i + 1) +
                  " does not follow timestamp " + std::to_string(i));
    }
  }
}

// Index of the timestamp of `sorted` nearest to `t` (the earlier one on a tie).
size_t Nearest(const std::vector<double>& sorted, double t) {
  const auto after = std::lower_bound(sorted.begin(), sorted.end(), t);
  if (after == sorted.begin()) return 0;
  if (after == sorted.end()) return sorted.size() - 1;
  const size_t upper = static_cast<size_t>(after - sorted.begin());
  return t - sorted[upper - 1] <= sorted[upper] - t ? upper - 1 : upper;
}

}  // namespace

void TimeAssociationOptions::Check() const {
  CheckOption(std::isfinite(max_difference_s) && max_difference_s >= 0.0, "max_difference_s",
              "must be a non-negative number of seconds, got " + std::to_string(max_difference_s));
}

TimeAssociation AssociateByTime(const std::vector<double>& gt_timestamps,
                                const std::vector<double>& est_timestamps,
                                const TimeAssociationOptions& options) {
  options.Check();
  CheckIncreasing(gt_timestamps, "ground-truth");
  CheckIncreasing(est_timestamps, "estimated");

  const bool gt_is_shorter = gt_timestamps.size() < est_timestamps.size();
  const std::vector<double>& shorter = gt_is_shorter ? gt_timestamps : est_timestamps;
  const std::vector<double>& longer = gt_is_shorter ? est_timestamps : gt_timestamps;
  TimeAssociation association;
  if (longer.empty()) return association;
  for (size_t i = 0; i < shorter.size(); ++i) {
    const size_t j = Nearest(longer, shorter[i]);
    if (std::abs(longer[j] - shorter[i]) > options.max_difference_s) continue;
    association.gt_indices.push_back(gt_is_shorter ? i : j);
    association.est_indices.push_back(gt_is_shorter ? j : i);
  }
  return association;
}

}  // namespace roadscale
