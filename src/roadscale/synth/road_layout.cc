#include "roadscale/synth/road_layout.h"

#include <algorithm>
#include <cmath>

namespace roadscale::synth {

LateralLayout MakeLateralLayout(const RoadOptions& options) {
  LateralLayout layout;
  const double w = options.lane_width;
  layout.lane_width = w;
  const bool fast = options.median_width > 0.0;  // a highway: longer dashes, wider lines
  const double line = fast ? 0.15 : 0.12;
  const double dash = fast ? 6.0 : 3.0, gap = fast ? 12.0 : 6.0;

  for (int k = 0; k < options.lanes_same; ++k) layout.same_lanes.push_back(k * w);
  // Right side: parking strip and shoulder outside the ego lane.
  const double ego_right = -0.5 * w;
  layout.has_parking = options.parking_width > 0.0;
  layout.parking_right = ego_right - 0.5 * options.parking_width;
  layout.right_edge = ego_right - options.parking_width - options.shoulder_width;
  if (!layout.has_parking || options.shoulder_width > 0.0) {
    layout.markings.push_back({ego_right + 0.5 * line + 0.1, line, 0.0, 0.0});
  }
  for (int k = 1; k < options.lanes_same; ++k) {
    layout.markings.push_back({(k - 0.5) * w, line, dash, gap});
  }
  double x = (options.lanes_same - 0.5) * w;  // left edge of the same-direction lanes
  if (options.lanes_opposite > 0) {
    if (options.median_width > 0.0) {
      layout.has_median = true;
      layout.markings.push_back({x - 0.5 * line - 0.1, line, 0.0, 0.0});
      layout.median_centre = x + 0.5 * options.median_width;
      x += options.median_width;
      layout.markings.push_back({x + 0.5 * line + 0.1, line, 0.0, 0.0});
    } else {
      layout.markings.push_back({x, line, dash, gap});
    }
    for (int k = 0; k < options.lanes_opposite; ++k) {
      if (k > 0) layout.markings.push_back({x + k * w, line, dash, gap});
      layout.opposite_lanes.push_back(x + (k + 0.5) * w);
    }
    x += options.lanes_opposite * w;
  }
  if (!layout.has_parking || options.shoulder_width > 0.0) {
    layout.markings.push_back({x - 0.5 * line - 0.1, line, 0.0, 0.0});
  }
  layout.parking_left = x + 0.5 * options.parking_width;
  layout.left_edge = x + options.parking_width + options.shoulder_width;
  const double side = options.sidewalk_width + options.verge_width;
  layout.right_outer = layout.right_edge - side;
  layout.left_outer = layout.left_edge + side;
  return layout;
}

RoadIndex::RoadIndex(const CentreLine& line, double u_begin, double u_end, double spacing)
    : line_(line) {
  for (double u = u_begin; u <= u_end + 1e-9; u += spacing) {
    const RoadFrame frame = line.FrameAt(u);
    const uint32_t index = static_cast<uint32_t>(u_.size());
    u_.push_back(u);
    xy_.push_back(frame.point.head<2>());
    left_.push_back(frame.horizontal_left.head<2>());
    const int64_t ix = static_cast<int64_t>(std::floor(frame.point.x() / cell_));
    const int64_t iy = static_cast<int64_t>(std::floor(frame.point.y() / cell_));
    grid_[Key(ix, iy)].push_back(index);
  }
}

RoadIndex::Nearest RoadIndex::Find(const Eigen::Vector2d& xy, double max_distance) const {
  Nearest best;
  const int64_t ix = static_cast<int64_t>(std::floor(xy.x() / cell_));
  const int64_t iy = static_cast<int64_t>(std::floor(xy.y() / cell_));
  const int64_t reach = static_cast<int64_t>(std::ceil(max_distance / cell_));
  double best_sq = max_distance * max_distance;
  uint32_t best_index = 0;
  bool found = false;
  for (int64_t dx = -reach; dx <= reach; ++dx) {
    for (int64_t dy = -reach; dy <= reach; ++dy) {
      const auto it = grid_.find(Key(ix + dx, iy + dy));
      if (it == grid_.end()) continue;
      for (const uint32_t index : it->second) {
        const double d = (xy_[index] - xy).squaredNorm();
        // Ties go to the lower u, so the answer does not depend on the grid's order.
        if (d < best_sq || (d == best_sq && found && index < best_index)) {
          best_sq = d;
          best_index = index;
          found = true;
        }
      }
    }
  }
  if (found) {
    best.u = u_[best_index];
    best.distance = std::sqrt(best_sq);
    best.lateral = (xy - xy_[best_index]).dot(left_[best_index]);
  }
  return best;
}

double RoadIndex::Reach(double u, int side, double from, double max_reach) const {
  const RoadFrame frame = line_.FrameAt(u);
  const Eigen::Vector2d origin = frame.point.head<2>();
  const Eigen::Vector2d direction = side * frame.horizontal_left.head<2>();
  double reach = from;
  for (double l = from + 1.0; l <= max_reach + 1e-9; l += 1.0) {
    const Nearest nearest = Find(origin + l * direction, l + 2.0);
    if (std::abs(nearest.u - u) > 1.5) break;
    reach = l;
  }
  return std::min(reach, max_reach);
}

bool RoadIndex::IsClear(const Eigen::Vector2d& xy, const LateralLayout& layout,
                        double margin) const {
  const double corridor = std::max(-layout.right_outer, layout.left_outer) + margin;
  const int64_t ix = static_cast<int64_t>(std::floor(xy.x() / cell_));
  const int64_t iy = static_cast<int64_t>(std::floor(xy.y() / cell_));
  const int64_t reach = static_cast<int64_t>(std::ceil(corridor / cell_));
  for (int64_t dx = -reach; dx <= reach; ++dx) {
    for (int64_t dy = -reach; dy <= reach; ++dy) {
      const auto it = grid_.find(Key(ix + dx, iy + dy));
      if (it == grid_.end()) continue;
      for (const uint32_t index : it->second) {
        const Eigen::Vector2d d = xy - xy_[index];
        if (d.squaredNorm() > corridor * corridor) continue;
        // Inside the corridor of this sample's cross-section?
        const Eigen::Vector2d left = left_[index];
        const Eigen::Vector2d forward(left.y(), -left.x());
        const double lateral = d.dot(left);
        if (std::abs(d.dot(forward)) > 1.0) continue;
        if (lateral > layout.right_outer - margin && lateral < layout.left_outer + margin) {
          return false;
        }
      }
    }
  }
  return true;
}

}  // namespace roadscale::synth
