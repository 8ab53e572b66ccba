#pragma once

#include <vector>

#include "roadscale/synth/centre_line.h"
#include "roadscale/synth/mesh.h"
#include "roadscale/synth/road_layout.h"
#include "roadscale/synth/scene_options.h"
#include "roadscale/util/random.h"

#include <Eigen/Core>

namespace roadscale::synth {

// A shadow on the ground as a rectangle in road coordinates (u along, l across), with
// soft edges; `strength` 1 removes all direct sunlight.
struct GroundShadow {
  double u_min = 0.0, u_max = 0.0, l_min = 0.0, l_max = 0.0;
  float strength = 0.8f;
};

// The dappled shadow of a tree crown on the ground, a disc in road coordinates.
struct TreeShadow {
  double u = 0.0, l = 0.0, radius = 0.0;
  uint32_t seed = 0;
};

// A piece of the static world: everything anchored between two arc positions, with a
// bounding sphere for view culling.
struct Chunk {
  Mesh mesh;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

struct StaticWorld {
  std::vector<Chunk> chunks;
  std::vector<GroundShadow> shadows;     // of parked cars, sorted by u_min
  std::vector<TreeShadow> tree_shadows;  // sorted by u
};

// The sun's shadow offset in road coordinates at arc position u for a point `height`
// metres above the ground: (du, dl).
Eigen::Vector2d ShadowOffset(const CentreLine& line, double u, double height,
                             const Eigen::Vector3d& sun);

// Road surface, kerbs, sidewalks, ground, buildings, walls, fences, trees, poles, signs
// and parked cars between arc positions u_begin and u_end.
StaticWorld BuildStaticWorld(const SceneOptions& options, const CentreLine& line,
                             const LateralLayout& layout, const RoadIndex& index,
                             const Eigen::Vector3d& sun, double u_begin, double u_end, Rng rng);

}  // namespace roadscale::synth
