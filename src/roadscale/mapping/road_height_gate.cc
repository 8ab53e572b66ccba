#include "roadscale/mapping/road_height_gate.h"

#include "roadscale/util/median.h"

namespace roadscale {

bool RoadHeightsAgree(const std::vector<double>& pair_heights,
                      const std::vector<double>& window_heights,
                      const std::vector<double>& window_pair_heights, double max_ratio) {
  const bool landmarks = static_cast<int>(window_heights.size()) >= kMinRoadLandmarksToCompare;
  if (!landmarks && window_pair_heights.empty()) return true;
  if (pair_heights.empty()) return false;
  const double ratio =
      Median(pair_heights) / Median(landmarks ? window_heights : window_pair_heights);
  return ratio <= max_ratio && ratio >= 1.0 / max_ratio;
}

}  // namespace roadscale
