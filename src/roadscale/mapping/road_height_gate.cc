#include "roadscale/mapping/road_height_gate.h"

#include <algorithm>

namespace roadscale {

double MedianOf(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

bool RoadHeightsAgree(const std::vector<double>& pair_heights,
                      const std::vector<double>& window_heights, double max_ratio) {
  if (static_cast<int>(window_heights.size()) < kMinRoadLandmarksToCompare) return true;
  if (pair_heights.empty()) return false;
  const double ratio = MedianOf(pair_heights) / MedianOf(window_heights);
  return ratio <= max_ratio && ratio >= 1.0 / max_ratio;
}

}  // namespace roadscale
