#include "roadscale/mapping/road_height_gate.h"

#include "roadscale/util/median.h"

namespace roadscale {

bool RoadHeightsAgree(const std::vector<double>& pair_heights,
                      const std::vector<double>& window_heights, double max_ratio) {
  if (static_cast<int>(window_heights.size()) < kMinRoadLandmarksToCompare) return true;
  if (pair_heights.empty()) return false;
  const double ratio = Median(pair_heights) / Median(window_heights);
  return ratio <= max_ratio && ratio >= 1.0 / max_ratio;
}

}  // namespace roadscale
