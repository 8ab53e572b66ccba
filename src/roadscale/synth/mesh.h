#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace roadscale::synth {

// What a surface is made of; selects the procedural texture (procedural_texture.h).
enum class Material : uint8_t {
  kAsphalt,
  kSidewalk,
  kKerb,
  kGrass,
  kPaving,
  kFacade,
  kRoof,
  kBrick,
  kConcrete,
  kFence,
  kFoliage,
  kBark,
  kMetal,
  kCarPaint,
  kCarGlass,
  kTyre,
  kCloth,
  kSkin,
  kSign,
};

struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
};

// Cityscapes train ids of the label images.
namespace label {
inline constexpr uint8_t kRoad = 0;
inline constexpr uint8_t kSidewalk = 1;
inline constexpr uint8_t kBuilding = 2;
inline constexpr uint8_t kWall = 3;
inline constexpr uint8_t kFence = 4;
inline constexpr uint8_t kPole = 5;
inline constexpr uint8_t kTrafficSign = 7;
inline constexpr uint8_t kVegetation = 8;
inline constexpr uint8_t kTerrain = 9;
inline constexpr uint8_t kSky = 10;
inline constexpr uint8_t kPerson = 11;
inline constexpr uint8_t kCar = 13;
}  // namespace label

// How a triangle looks and what it is. `variant` seeds per-object texture choices (window
// layout, slab size); `tint` is the base colour.
struct SurfaceStyle {
  Material material = Material::kConcrete;
  uint8_t label = label::kBuilding;
  uint32_t variant = 0;
  Rgb tint{0.5f, 0.5f, 0.5f};
  // Lit from both sides (thin panels); otherwise the winding gives the lit side.
  bool two_sided = false;
  // Texture coordinates are the road's (u, l): the surface receives the shadows that the
  // renderer casts on the ground.
  bool road_coords = false;
};

struct MeshTriangle {
  uint32_t v[3];
  SurfaceStyle style;
};

// A triangle mesh with texture coordinates in metres on the surface (s along, t across or
// up). Vertices are not shared between faces with different texture coordinates.
struct Mesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector2f> texcoords;
  std::vector<MeshTriangle> triangles;

  uint32_t AddVertex(const Eigen::Vector3d& position, double s, double t);
  void AddTriangle(uint32_t a, uint32_t b, uint32_t c, const SurfaceStyle& style);
  // A quad p0 p1 p2 p3, counter-clockwise seen from its front, as two triangles; the
  // texture coordinates are given per corner.
  void AddQuad(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
               const Eigen::Vector3d& p3, const Eigen::Vector2d& st0, const Eigen::Vector2d& st1,
               const Eigen::Vector2d& st2, const Eigen::Vector2d& st3, const SurfaceStyle& style);
  // A box standing on `base` (bottom centre) with axes x (length), y (width), z (up), the
  // columns of `axes`. Side faces get s along the face from its left edge and t = height
  // above the bottom plus `t_offset`; the top gets (x, y) in metres. Faces with a null
  // style are left out; the bottom is never drawn.
  void AddBox(const Eigen::Vector3d& base, const Eigen::Matrix3d& axes, double length, double width,
              double height, const SurfaceStyle* sides, const SurfaceStyle* top,
              double t_offset = 0.0);
  void Append(const Mesh& other);
  void Clear();
  bool empty() const { return triangles.empty(); }
  Eigen::AlignedBox3d Bounds() const;
  // Unit normal of a triangle from its winding.
  Eigen::Vector3d Normal(const MeshTriangle& triangle) const;
};

}  // namespace roadscale::synth
