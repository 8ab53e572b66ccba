#include "roadscale/synth/mesh.h"

namespace roadscale::synth {

uint32_t Mesh::AddVertex(const Eigen::Vector3d& position, double s, double t) {
  positions.push_back(position);
  texcoords.emplace_back(static_cast<float>(s), static_cast<float>(t));
  return static_cast<uint32_t>(positions.size() - 1);
}

void Mesh::AddTriangle(uint32_t a, uint32_t b, uint32_t c, const SurfaceStyle& style) {
  triangles.push_back(MeshTriangle{{a, b, c}, style});
}

void Mesh::AddQuad(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                   const Eigen::Vector3d& p3, const Eigen::Vector2d& st0,
                   const Eigen::Vector2d& st1, const Eigen::Vector2d& st2,
                   const Eigen::Vector2d& st3, const SurfaceStyle& style) {
  const uint32_t a = AddVertex(p0, st0.x(), st0.y());
  const uint32_t b = AddVertex(p1, st1.x(), st1.y());
  const uint32_t c = AddVertex(p2, st2.x(), st2.y());
  const uint32_t d = AddVertex(p3, st3.x(), st3.y());
  AddTriangle(a, b, c, style);
  AddTriangle(a, c, d, style);
}

void Mesh::AddBox(const Eigen::Vector3d& base, const Eigen::Matrix3d& axes, double length,
                  double width, double height, const SurfaceStyle* sides, const SurfaceStyle* top,
                  double t_offset) {
  const Eigen::Vector3d x = axes.col(0) * (0.5 * length);
  const Eigen::Vector3d y = axes.col(1) * (0.5 * width);
  const Eigen::Vector3d z = axes.col(2) * height;
  // Bottom corners counter-clockwise seen from above: (-x,-y), (+x,-y), (+x,+y), (-x,+y).
  const Eigen::Vector3d c[4] = {base - x - y, base + x - y, base + x + y, base - x + y};
  const double face_length[4] = {length, width, length, width};
  for (int k = 0; k < 4; ++k) {
    // Face k, seen from outside, runs from corner k to corner k+1 (left to right).
    if (sides == nullptr) break;
    const Eigen::Vector3d& a = c[k];
    const Eigen::Vector3d& b = c[(k + 1) % 4];
    const double w = face_length[k];
    AddQuad(a, b, b + z, a + z, {0.0, t_offset}, {w, t_offset}, {w, t_offset + height},
            {0.0, t_offset + height}, *sides);
  }
  if (top != nullptr) {
    AddQuad(c[0] + z, c[1] + z, c[2] + z, c[3] + z, {0.0, 0.0}, {length, 0.0}, {length, width},
            {0.0, width}, *top);
  }
}

void Mesh::Append(const Mesh& other) {
  const uint32_t offset = static_cast<uint32_t>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  texcoords.insert(texcoords.end(), other.texcoords.begin(), other.texcoords.end());
  for (MeshTriangle triangle : other.triangles) {
    for (uint32_t& v : triangle.v) v += offset;
    triangles.push_back(triangle);
  }
}

void Mesh::Clear() {
  positions.clear();
  texcoords.clear();
  triangles.clear();
}

Eigen::AlignedBox3d Mesh::Bounds() const {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : positions) box.extend(p);
  return box;
}

Eigen::Vector3d Mesh::Normal(const MeshTriangle& triangle) const {
  const Eigen::Vector3d& a = positions[triangle.v[0]];
  const Eigen::Vector3d& b = positions[triangle.v[1]];
  const Eigen::Vector3d& c = positions[triangle.v[2]];
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double norm = n.norm();
  return norm > 0.0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::UnitZ();
}

}  // namespace roadscale::synth
