#pragma once

#include <vector>

namespace roadscale {

// Road landmarks the window must hold before a new keyframe pair's road points are compared
// with them: fewer say nothing about the map's scale.
constexpr int kMinRoadLandmarksToCompare = 3;

// Whether a keyframe pair's road points, at `pair_heights` under their anchor (map units),
// agree with the window's road: their median within a factor `max_ratio` (> 1) of the median
// of the window's road landmarks' heights `window_heights`, or, with fewer than
// kMinRoadLandmarksToCompare of those, of the camera heights its road alignments measured
// (`window_pair_heights`: each from thousands of road pixels, so one is enough to compare
// with). With neither there is nothing to compare with, and they agree.
bool RoadHeightsAgree(const std::vector<double>& pair_heights,
                      const std::vector<double>& window_heights,
                      const std::vector<double>& window_pair_heights, double max_ratio);

}  // namespace roadscale
