#pragma once

#include <unordered_map>
#include <vector>

#include "roadscale/synth/centre_line.h"
#include "roadscale/synth/procedural_texture.h"
#include "roadscale/synth/scene_options.h"

#include <Eigen/Core>

namespace roadscale::synth {

// Where things are across the road, as lateral offsets l from the ego lane centre (the
// centre line, l = 0), positive to the left.
struct LateralLayout {
  double lane_width = 3.5;
  std::vector<double> same_lanes;      // lane centres in the ego direction (first: ego)
  std::vector<double> opposite_lanes;  // lane centres of oncoming traffic
  bool has_parking = false;
  double parking_right = 0.0, parking_left = 0.0;  // centres of the parking strips
  bool has_median = false;
  double median_centre = 0.0;
  double right_edge = 0.0, left_edge = 0.0;    // edges of the asphalt (kerb lines)
  double right_outer = 0.0, left_outer = 0.0;  // outer edges of sidewalk + verge
  std::vector<LaneMarking> markings;
};

LateralLayout MakeLateralLayout(const RoadOptions& options);

// Samples of the centre line in a grid, to ask which part of the road a ground point
// belongs to (the nearest sample) and how far it is from the road.
class RoadIndex {
 public:
  RoadIndex(const CentreLine& line, double u_begin, double u_end, double spacing = 1.0);

  struct Nearest {
    double u = 0.0;           // arc position of the nearest sample
    double distance = 1e300;  // horizontal distance to it
    double lateral = 0.0;     // signed horizontal offset along the sample's left direction
  };
  // The nearest sample within `max_distance` (distance stays 1e300 when there is none).
  Nearest Find(const Eigen::Vector2d& xy, double max_distance) const;

  // How far (metres) the roadside strip at u may reach on one side (+1 left, -1 right)
  // before the ground belongs to another part of the road, up to `max_reach`.
  double Reach(double u, int side, double from, double max_reach) const;

  // True when the horizontal point is clear of every part of the road by the layout's
  // outer edges plus `margin`.
  bool IsClear(const Eigen::Vector2d& xy, const LateralLayout& layout, double margin) const;

 private:
  int64_t Key(int64_t ix, int64_t iy) const { return ix * 1000003LL + iy; }
  const CentreLine& line_;
  double cell_ = 10.0;
  std::vector<double> u_;
  std::vector<Eigen::Vector2d> xy_, left_;
  std::unordered_map<int64_t, std::vector<uint32_t>> grid_;
};

}  // namespace roadscale::synth
