#include "roadscale/synth/static_world.h"

#include <algorithm>
#include <cmath>

#include "roadscale/synth/object_models.h"

namespace roadscale::synth {
namespace {

constexpr double kChunkLength = 20.0;  // metres of road per chunk
constexpr double kRibbonStep = 0.5;    // metres between cross-sections of the road mesh

SurfaceStyle MakeStyle(Material material, uint8_t label_id, const Rgb& tint, uint32_t variant,
                       bool road_coords = false, bool two_sided = false) {
  SurfaceStyle style;
  style.material = material;
  style.label = label_id;
  style.tint = tint;
  style.variant = variant;
  style.road_coords = road_coords;
  style.two_sided = two_sided;
  return style;
}

Mesh Transformed(const Mesh& mesh, const Eigen::Matrix3d& rotation,
                 const Eigen::Vector3d& translation) {
  Mesh out = mesh;
  for (Eigen::Vector3d& p : out.positions) p = rotation * p + translation;
  return out;
}

// A horizontal frame at arc position u: x along the road, y to the left, z up.
Eigen::Matrix3d HorizontalAxes(const RoadFrame& frame) {
  Eigen::Matrix3d axes;
  axes.col(0) = Eigen::Vector3d(std::cos(frame.heading), std::sin(frame.heading), 0.0);
  axes.col(1) = frame.horizontal_left;
  axes.col(2) = Eigen::Vector3d::UnitZ();
  return axes;
}

class WorldBuilder {
 public:
  WorldBuilder(const SceneOptions& options, const CentreLine& line, const LateralLayout& layout,
               const RoadIndex& index, const Eigen::Vector3d& sun, double u_begin, double u_end,
               Rng rng)
      : options_(options),
        line_(line),
        layout_(layout),
        index_(index),
        sun_(sun),
        u_begin_(u_begin),
        u_end_(u_end),
        rng_(rng) {
    const int count = std::max(1, static_cast<int>(std::ceil((u_end - u_begin) / kChunkLength)));
    world_.chunks.resize(count);
  }

  StaticWorld Build() {
    Rng ribbon_rng = rng_.Fork(1);
    BuildRibbon(ribbon_rng);
    // One generator per side and kind of object, each used in order of u: a longer
    // sequence gets the same world at its start.
    for (int side : {-1, 1}) {
      Rng building_rng = rng_.Fork(10 + side);
      BuildFrontage(side, building_rng);
    }
    BuildStreetFurniture();
    if (layout_.has_parking && options_.traffic.parked_fraction > 0.0) {
      for (int side : {-1, 1}) {
        Rng parked_rng = rng_.Fork(20 + side);
        BuildParkedCars(side, parked_rng);
      }
    }
    Rng backdrop_rng = rng_.Fork(5);
    BuildBackdrop(backdrop_rng);
    for (Chunk& chunk : world_.chunks) {
      if (chunk.mesh.empty()) continue;
      const Eigen::AlignedBox3d box = chunk.mesh.Bounds();
      chunk.centre = box.center();
      chunk.radius = 0.5 * box.diagonal().norm();
    }
    std::sort(world_.shadows.begin(), world_.shadows.end(),
              [](const GroundShadow& a, const GroundShadow& b) { return a.u_min < b.u_min; });
    std::sort(world_.tree_shadows.begin(), world_.tree_shadows.end(),
              [](const TreeShadow& a, const TreeShadow& b) { return a.u < b.u; });
    return std::move(world_);
  }

 private:
  Mesh& ChunkAt(double u) {
    const int i = static_cast<int>(std::floor((u - u_begin_) / kChunkLength));
    return world_.chunks[std::clamp(i, 0, static_cast<int>(world_.chunks.size()) - 1)].mesh;
  }

  double Kerb() const { return options_.road.kerb_height; }
  // Distance from the centre line to the outer edge of sidewalk + verge on a side.
  double Outer(int side) const { return side > 0 ? layout_.left_outer : -layout_.right_outer; }
  double Edge(int side) const { return side > 0 ? layout_.left_edge : -layout_.right_edge; }

  Eigen::Vector3d Ground(const RoadFrame& frame, double l) const {
    return line_.SurfacePoint(frame, l, Kerb());
  }

  bool Clear(const Eigen::Vector3d& p, double margin) const {
    return index_.IsClear(p.head<2>(), layout_, margin);
  }

  void BuildRibbon(Rng& rng) {
    const RoadOptions& road = options_.road;
    const uint32_t v = static_cast<uint32_t>(rng.NextU64());
    const float grey = static_cast<float>(rng.Uniform(0.4, 0.46));
    const SurfaceStyle asphalt =
        MakeStyle(Material::kAsphalt, label::kRoad, {grey, grey, grey * 1.02f}, v, true);
    const SurfaceStyle sidewalk =
        MakeStyle(Material::kSidewalk, label::kSidewalk, {0.64f, 0.62f, 0.6f}, v + 1, true);
    const SurfaceStyle kerb =
        MakeStyle(Material::kKerb, label::kSidewalk, {0.72f, 0.72f, 0.7f}, v + 2, true);
    const SurfaceStyle grass =
        MakeStyle(Material::kGrass, label::kTerrain, {0.3f, 0.4f, 0.2f}, v + 3, true);
    const SurfaceStyle ground = road.paved_ground ? MakeStyle(Material::kPaving, label::kSidewalk,
                                                              {0.56f, 0.55f, 0.53f}, v + 4, true)
                                                  : grass;
    const SurfaceStyle barrier =
        MakeStyle(Material::kConcrete, label::kWall, {0.8f, 0.8f, 0.78f}, v + 5);
    const SurfaceStyle rail =
        MakeStyle(Material::kMetal, label::kFence, {0.6f, 0.62f, 0.64f}, v + 6, false, true);

    // The cross-section, right to left: (l, height, style of the part to the next point).
    // Outer ends move with the reach of the ground; everything else is fixed.
    struct Point {
      double l, h;
      const SurfaceStyle* style;  // of the segment from this point to the next
    };
    const double kerb_h = Kerb();
    const bool has_kerb = kerb_h > 0.0;
    const double top = (has_kerb && road.sidewalk_width > 0.3) ? 0.15 : 0.0;
    auto section = [&](double reach_right, double reach_left) {
      std::vector<Point> s;
      s.push_back({-reach_right, kerb_h, &ground});
      s.push_back({layout_.right_outer, kerb_h, &grass});
      s.push_back({layout_.right_edge - road.sidewalk_width, kerb_h, &sidewalk});
      s.push_back({layout_.right_edge - top, kerb_h, &kerb});
      if (has_kerb) s.push_back({layout_.right_edge, kerb_h, &kerb});
      s.push_back({layout_.right_edge, 0.0, &asphalt});
      s.push_back({layout_.left_edge, 0.0, has_kerb ? &kerb : &grass});
      if (has_kerb) s.push_back({layout_.left_edge, kerb_h, &kerb});
      s.push_back({layout_.left_edge + top, kerb_h, &sidewalk});
      s.push_back({layout_.left_edge + road.sidewalk_width, kerb_h, &grass});
      s.push_back({layout_.left_outer, kerb_h, &ground});
      s.push_back({reach_left, kerb_h, nullptr});
      return s;
    };

    const int steps = static_cast<int>(std::ceil((u_end_ - u_begin_) / kRibbonStep));
    std::vector<Point> previous;
    RoadFrame previous_frame = line_.FrameAt(u_begin_);
    for (int i = 0; i <= steps; ++i) {
      const double u = u_begin_ + i * kRibbonStep;
      const RoadFrame frame = line_.FrameAt(u);
      const double max_right = -layout_.right_outer + road.ground_width;
      const double max_left = layout_.left_outer + road.ground_width;
      const double reach_right = index_.Reach(u, -1, -layout_.right_outer, max_right);
      const double reach_left = index_.Reach(u, 1, layout_.left_outer, max_left);
      std::vector<Point> current = section(reach_right, reach_left);
      if (i > 0) {
        const double u0 = u - kRibbonStep;
        Mesh& mesh = ChunkAt(0.5 * (u0 + u));
        for (size_t k = 0; k + 1 < current.size(); ++k) {
          const Point& a0 = previous[k];
          const Point& b0 = previous[k + 1];
          const Point& a1 = current[k];
          const Point& b1 = current[k + 1];
          if (a0.l == b0.l && a0.h == b0.h) continue;  // an absent part (zero width)
          // The surface twists where the bank or grade changes; narrow quads keep the mesh
          // within a millimetre of it on the road.
          const double max_width = a0.style->label == label::kRoad ? 1.0 : 3.0;
          const int parts = static_cast<int>(
              std::ceil(std::max(std::abs(b0.l - a0.l), std::abs(b1.l - a1.l)) / max_width));
          auto at = [this](const RoadFrame& f, const Point& a, const Point& b, double k) {
            const double l = a.l + k * (b.l - a.l), h = a.h + k * (b.h - a.h);
            return line_.SurfacePoint(f, l, h);
          };
          for (int j = 0; j < std::max(1, parts); ++j) {
            const double k0 = static_cast<double>(j) / std::max(1, parts);
            const double k1 = static_cast<double>(j + 1) / std::max(1, parts);
            const double l00 = a0.l + k0 * (b0.l - a0.l), l01 = a0.l + k1 * (b0.l - a0.l);
            const double l10 = a1.l + k0 * (b1.l - a1.l), l11 = a1.l + k1 * (b1.l - a1.l);
            // Quad corners counter-clockwise seen from above / from the road.
            mesh.AddQuad(at(previous_frame, a0, b0, k0), at(frame, a1, b1, k0),
                         at(frame, a1, b1, k1), at(previous_frame, a0, b0, k1), {u0, l00}, {u, l10},
                         {u, l11}, {u0, l01}, *a0.style);
          }
        }
        if (layout_.has_median) {
          const double m = layout_.median_centre;
          const double half = 0.25, height = 0.85;
          auto at = [&](const RoadFrame& f, double l, double h) {
            return line_.SurfacePoint(f, l, h);
          };
          for (int side : {-1, 1}) {
            const double l = m + side * half;
            if (side < 0) {
              mesh.AddQuad(at(previous_frame, l, 0.0), at(frame, l, 0.0), at(frame, l, height),
                           at(previous_frame, l, height), {u0, 0.0}, {u, 0.0}, {u, height},
                           {u0, height}, barrier);
            } else {
              mesh.AddQuad(at(frame, l, 0.0), at(previous_frame, l, 0.0),
                           at(previous_frame, l, height), at(frame, l, height), {u, 0.0}, {u0, 0.0},
                           {u0, height}, {u, height}, barrier);
            }
          }
          mesh.AddQuad(at(previous_frame, m - half, height), at(frame, m - half, height),
                       at(frame, m + half, height), at(previous_frame, m + half, height), {u0, 0.0},
                       {u, 0.0}, {u, 0.5}, {u0, 0.5}, barrier);
          // Guard rails along both outer edges.
          for (double l : {layout_.right_edge - 0.6, layout_.left_edge + 0.6}) {
            mesh.AddQuad(at(previous_frame, l, 0.45), at(frame, l, 0.45), at(frame, l, 0.8),
                         at(previous_frame, l, 0.8), {u0, 0.0}, {u, 0.0}, {u, 0.35}, {u0, 0.35},
                         rail);
          }
        }
      }
      if (layout_.has_median && i % 4 == 0) {
        const Eigen::Matrix3d axes = HorizontalAxes(frame);
        for (double l : {layout_.right_edge - 0.6, layout_.left_edge + 0.6}) {
          ChunkAt(u).AddBox(line_.SurfacePoint(frame, l, -0.2), axes, 0.12, 0.12, 0.95, &rail,
                            &rail);
        }
      }
      previous = std::move(current);
      previous_frame = frame;
    }
  }

  // Buildings along one side, with walls, fences, hedges and trees in the gaps.
  void BuildFrontage(int side, Rng& rng) {
    const SceneryOptions& scenery = options_.scenery;
    double u = u_begin_ + rng.Uniform(0.0, 5.0);
    while (u < u_end_) {
      if (rng.Bernoulli(scenery.building_fraction)) {
        double width = rng.Uniform(scenery.building_width_min, scenery.building_width_max);
        const bool placed =
            AddBuilding(side, u, width, rng) || AddBuilding(side, u, width *= 0.5, rng);
        u += placed ? width + rng.Uniform(0.0, 1.5) : 3.0;
      } else {
        const double gap = rng.Uniform(4.0, 14.0);
        FillGap(side, u, gap, rng);
        u += gap;
      }
    }
  }

  bool AddBuilding(int side, double u, double width, Rng& rng) {
    const SceneryOptions& scenery = options_.scenery;
    const double u_mid = u + 0.5 * width;
    const RoadFrame frame = line_.FrameAt(u_mid);
    const Eigen::Matrix3d axes = HorizontalAxes(frame);
    const double setback = rng.Uniform(scenery.building_setback_min, scenery.building_setback_max);
    const double depth = rng.Uniform(8.0, 15.0);
    const double height = rng.Uniform(scenery.building_height_min, scenery.building_height_max);
    const double front = Outer(side) + setback;
    const Eigen::Vector3d origin = frame.point;
    auto corner = [&](double along, double lateral) {
      return Eigen::Vector3d(origin + along * axes.col(0) + side * lateral * axes.col(1));
    };
    const double half = 0.5 * width;
    for (const Eigen::Vector3d& p : {corner(-half, front), corner(half, front), corner(0.0, front),
                                     corner(-half, front + depth), corner(half, front + depth)}) {
      if (!Clear(p, -0.1)) return false;
    }
    // Sink the box below the lowest ground under it; windows count from the ground in front.
    const double ground_front = Ground(frame, side * front).z();
    const double slope = std::abs(frame.grade) * half + std::abs(frame.lateral.z()) * depth;
    const double base = ground_front - slope - 0.5;
    const Eigen::Vector3d base_centre =
        corner(0.0, front + 0.5 * depth) + Eigen::Vector3d(0.0, 0.0, base - origin.z());
    static const Rgb kPlaster[] = {
        {0.86f, 0.84f, 0.78f}, {0.78f, 0.78f, 0.76f}, {0.88f, 0.82f, 0.7f}, {0.72f, 0.66f, 0.6f},
        {0.82f, 0.74f, 0.72f}, {0.64f, 0.64f, 0.66f}, {0.9f, 0.9f, 0.88f},  {0.6f, 0.5f, 0.42f}};
    const Rgb tint = kPlaster[rng.UniformInt(0, 7)];
    const SurfaceStyle facade =
        MakeStyle(Material::kFacade, label::kBuilding, tint, static_cast<uint32_t>(rng.NextU64()));
    const SurfaceStyle roof = MakeStyle(Material::kRoof, label::kBuilding, {0.3f, 0.25f, 0.23f}, 0);
    ChunkAt(u_mid).AddBox(base_centre, axes, width, depth, ground_front - base + height, &facade,
                          &roof, -(ground_front - base));
    return true;
  }

  void FillGap(int side, double u, double gap, Rng& rng) {
    const SceneryOptions& scenery = options_.scenery;
    const double line_l = Outer(side) + 0.3;
    if (rng.Bernoulli(scenery.wall_probability)) {
      const int kind = rng.UniformInt(0, 2);
      const double height = kind == 2 ? rng.Uniform(1.0, 1.6) : rng.Uniform(1.0, 2.2);
      const double thickness = kind == 0 ? 0.3 : (kind == 1 ? 0.06 : 0.8);
      SurfaceStyle style;
      if (kind == 0) {
        const bool brick = rng.Bernoulli(0.5);
        style = MakeStyle(brick ? Material::kBrick : Material::kConcrete, label::kWall,
                          brick ? Rgb{0.55f, 0.38f, 0.3f} : Rgb{0.66f, 0.65f, 0.62f},
                          static_cast<uint32_t>(rng.NextU64()));
      } else if (kind == 1) {
        style = MakeStyle(Material::kFence, label::kFence, {0.5f, 0.45f, 0.38f},
                          static_cast<uint32_t>(rng.NextU64()), false, true);
      } else {
        style = MakeStyle(Material::kFoliage, label::kVegetation, {0.22f, 0.32f, 0.15f},
                          static_cast<uint32_t>(rng.NextU64()));
      }
      // Straight pieces of at most 4 m follow curves.
      const int pieces = std::max(1, static_cast<int>(std::ceil(gap / 4.0)));
      const double step = gap / pieces;
      for (int k = 0; k < pieces; ++k) {
        const double um = u + (k + 0.5) * step;
        const RoadFrame frame = line_.FrameAt(um);
        const Eigen::Matrix3d axes = HorizontalAxes(frame);
        const double l = side * (line_l + 0.5 * thickness);
        const Eigen::Vector3d base = Ground(frame, l) - Eigen::Vector3d(0.0, 0.0, 0.4);
        const Eigen::Vector3d ends[2] = {base - 0.5 * step * axes.col(0),
                                         base + 0.5 * step * axes.col(0)};
        if (!Clear(ends[0], -0.1) || !Clear(ends[1], -0.1)) continue;
        ChunkAt(um).AddBox(base, axes, step + 0.02, thickness, height + 0.4, &style, &style, -0.4);
      }
    }
    if (rng.Bernoulli(scenery.vegetation_probability)) {
      const int trees = rng.UniformInt(1, 3);
      for (int k = 0; k < trees; ++k) {
        const double ut = u + rng.Uniform(0.1, 0.9) * gap;
        const RoadFrame frame = line_.FrameAt(ut);
        const double l = side * (Outer(side) + rng.Uniform(3.0, 9.0));
        const Eigen::Vector3d base = Ground(frame, l);
        const double radius = rng.Uniform(2.0, 3.5);
        if (!Clear(base, radius - 2.0)) continue;
        AddTreeAt(ut, l, base, rng.Uniform(7.0, 13.0), radius, rng);
      }
    }
  }

  void AddTreeAt(double u, double l, const Eigen::Vector3d& base, double height, double radius,
                 Rng& rng) {
    AddTree(ChunkAt(u), base, height, radius, static_cast<uint32_t>(rng.NextU64()), rng);
    if (options_.texture.shadows) {
      const Eigen::Vector2d offset = ShadowOffset(line_, u, height - radius, sun_);
      world_.tree_shadows.push_back(
          {u + offset.x(), l + offset.y(), 0.85 * radius, static_cast<uint32_t>(rng.NextU64())});
    }
  }

  void BuildStreetFurniture() {
    const SceneryOptions& scenery = options_.scenery;
    const RoadOptions& road = options_.road;
    // Street trees on the sidewalk (or the verge) near the kerb.
    if (scenery.tree_spacing > 0.0) {
      for (int side : {-1, 1}) {
        Rng rng = rng_.Fork(30 + side);
        double offset;
        if (road.sidewalk_width >= 1.5) {
          offset = Edge(side) + 0.9;
        } else if (road.verge_width >= 2.0) {
          offset = Edge(side) + road.sidewalk_width + 0.5 * road.verge_width;
        } else {
          continue;
        }
        for (double u = u_begin_ + rng.Uniform(0.0, scenery.tree_spacing); u < u_end_;
             u += scenery.tree_spacing * rng.Uniform(0.8, 1.2)) {
          if (!rng.Bernoulli(scenery.tree_probability)) continue;
          const RoadFrame frame = line_.FrameAt(u);
          const double l = side * offset;
          const double crown_radius = rng.Uniform(1.8, 3.0);  // one draw a statement (traffic.cc)
          const double height = rng.Uniform(6.0, 11.0);
          AddTreeAt(u, l, Ground(frame, l), height, crown_radius, rng);
        }
      }
    }
    if (scenery.pole_spacing > 0.0) {
      Rng rng = rng_.Fork(40);
      int side = -1;
      for (double u = u_begin_ + rng.Uniform(0.0, scenery.pole_spacing); u < u_end_;
           u += scenery.pole_spacing * rng.Uniform(0.85, 1.15)) {
        const RoadFrame frame = line_.FrameAt(u);
        const double offset = road.sidewalk_width > 0.8 ? Edge(side) + 0.45 : Edge(side) + 1.2;
        const double l = side * offset;
        Eigen::Matrix3d axes;
        axes.col(1) = side * frame.horizontal_left;
        axes.col(2) = Eigen::Vector3d::UnitZ();
        axes.col(0) = axes.col(1).cross(axes.col(2));
        AddStreetLight(ChunkAt(u), Ground(frame, l), axes, rng.Uniform(6.0, 8.0));
        if (options_.scenery.building_fraction > 0.0) side = -side;
      }
      rng = rng_.Fork(41);
      for (double u = u_begin_ + rng.Uniform(20.0, 80.0); u < u_end_;
           u += rng.Uniform(50.0, 150.0)) {
        const RoadFrame frame = line_.FrameAt(u);
        const double l = layout_.right_edge - (road.sidewalk_width > 0.8 ? 0.4 : 1.0);
        AddTrafficSign(ChunkAt(u), Ground(frame, l), HorizontalAxes(frame),
                       static_cast<uint32_t>(rng.UniformInt(0, 1000)));
      }
    }
  }

  void BuildParkedCars(int side, Rng& rng) {
    const double lane = side > 0 ? layout_.parking_left : layout_.parking_right;
    double u = u_begin_ + rng.Uniform(0.0, 6.0);
    while (u < u_end_) {
      if (!rng.Bernoulli(options_.traffic.parked_fraction)) {
        u += rng.Uniform(3.0, 12.0);
        continue;
      }
      const CarShape shape = RandomCarShape(rng);
      const Rgb paint = RandomCarPaint(rng);
      const uint32_t variant = static_cast<uint32_t>(rng.NextU64());
      const double uc = u + 0.5 * shape.length;
      const double l = lane + rng.Uniform(-0.15, 0.15);
      const double yaw = rng.Uniform(-0.03, 0.03);
      u += shape.length + rng.Uniform(0.6, 2.5);
      const RoadFrame frame = line_.FrameAt(uc);
      if (std::abs(frame.curvature) > 1.0 / 40.0) continue;
      // Parked in the direction of their side's traffic.
      const double direction = (side > 0 && options_.road.lanes_opposite > 0) ? -1.0 : 1.0;
      Eigen::Matrix3d axes;
      const Eigen::Vector3d forward =
          direction * (std::cos(yaw) * frame.tangent + std::sin(yaw) * frame.lateral);
      axes.col(0) = forward;
      axes.col(2) = frame.normal;
      axes.col(1) = frame.normal.cross(forward);
      const Eigen::Vector3d position = line_.SurfacePoint(frame, l);
      ChunkAt(uc).Append(Transformed(MakeCar(shape, paint, variant), axes, position));
      if (options_.texture.shadows) {
        const Eigen::Vector2d offset = ShadowOffset(line_, uc, 0.8 * shape.height, sun_);
        GroundShadow shadow;
        shadow.u_min = uc - 0.5 * shape.length + std::min(0.0, offset.x());
        shadow.u_max = uc + 0.5 * shape.length + std::max(0.0, offset.x());
        shadow.l_min = l - 0.5 * shape.width + std::min(0.0, offset.y());
        shadow.l_max = l + 0.5 * shape.width + std::max(0.0, offset.y());
        world_.shadows.push_back(shadow);
      }
    }
  }

  void BuildBackdrop(Rng& rng) {
    const double rate = options_.scenery.backdrop_trees;
    if (rate <= 0.0) return;
    for (int side : {-1, 1}) {
      Rng side_rng = rng.Fork(side + 2);
      for (double u = u_begin_ + side_rng.Uniform(0.0, 200.0 / rate); u < u_end_;
           u += side_rng.Uniform(0.0, 200.0 / rate)) {
        const double reach =
            index_.Reach(u, side, Outer(side), Outer(side) + options_.road.ground_width);
        const double height = side_rng.Uniform(8.0, 16.0);
        const double radius = side_rng.Uniform(2.5, 5.0);
        if (reach < Outer(side) + 4.0 + radius) continue;
        const double l = side * (reach - side_rng.Uniform(0.0, 4.0));
        const RoadFrame frame = line_.FrameAt(u);
        const Eigen::Vector3d base = Ground(frame, l);
        if (!Clear(base, radius)) continue;
        AddTreeAt(u, l, base, height, radius, side_rng);
      }
    }
  }

  const SceneOptions& options_;
  const CentreLine& line_;
  const LateralLayout& layout_;
  const RoadIndex& index_;
  Eigen::Vector3d sun_;
  double u_begin_, u_end_;
  Rng rng_;
  StaticWorld world_;
};

}  // namespace

Eigen::Vector2d ShadowOffset(const CentreLine& line, double u, double height,
                             const Eigen::Vector3d& sun) {
  const RoadFrame frame = line.FrameAt(u);
  const Eigen::Vector2d horizontal = -height * sun.head<2>() / std::max(0.05, sun.z());
  const Eigen::Vector2d along(std::cos(frame.heading), std::sin(frame.heading));
  return {horizontal.dot(along), horizontal.dot(frame.horizontal_left.head<2>())};
}

StaticWorld BuildStaticWorld(const SceneOptions& options, const CentreLine& line,
                             const LateralLayout& layout, const RoadIndex& index,
                             const Eigen::Vector3d& sun, double u_begin, double u_end, Rng rng) {
  return WorldBuilder(options, line, layout, index, sun, u_begin, u_end, rng).Build();
}

}  // namespace roadscale::synth
