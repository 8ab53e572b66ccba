#pragma once

#include <vector>

namespace roadscale {

// Road landmarks the window must hold before a new keyframe pair's road points are compared
// with them: fewer say nothing about the map's scale.
constexpr int kMinRoadLandmarksToCompare = 3;

// Whether a keyframe pair's road points, at `pair_heights` under their anchor (map units),
// agree with the window's road landmarks at `window_heights`: their medians within a factor
// `max_ratio` (> 1) of each other. With fewer than kMinRoadLandmarksToCompare window heights
// there is nothing to compare with, and they agree.
bool RoadHeightsAgree(const std::vector<double>& pair_heights,
                      const std::vector<double>& window_heights, double max_ratio);

}  // namespace roadscale
