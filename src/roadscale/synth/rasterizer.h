#pragma once

#include <cstdint>
#include <vector>

#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/geometry/rigid3.h"
#include "roadscale/synth/mesh.h"

#include <Eigen/Core>

namespace roadscale::synth {

// A triangle after near-plane clipping and projection, with the affine screen functions
// that give exact per-pixel values: 1/z = inv_z . (x, y, 1) (from the triangle's plane),
// and s/z, t/z likewise (perspective-correct texture coordinates).
struct ScreenTriangle {
  double x[3], y[3];
  double inv_z[3], s_z[3], t_z[3];
  const SurfaceStyle* style = nullptr;
  float light = 1.0f;   // direct-light factor from the orientation to the sun
  bool moving = false;  // part of an object that moves in the world at this instant
};

// A z-buffer rasterizer for an undistorted pinhole camera. Pixel centres sit at integer
// coordinates; a pixel belongs to every triangle whose closed area contains its centre, and
// the nearest one wins (the first one added on exact ties), so the result does not depend
// on how the rows are split between threads.
class Rasterizer {
 public:
  Rasterizer(const PinholeCamera& camera, double near_distance, double far_distance);

  // Starts a frame; `sun_in_cam` is the unit direction towards the sun in the camera frame.
  void BeginFrame(const Eigen::Vector3d& sun_in_cam, double ambient);
  // Adds the triangles of `mesh` (coordinates in its own frame) seen from the camera;
  // `moving` marks an object that moves in the world. The mesh must stay alive until the
  // frame is shaded.
  void AddMesh(const Mesh& mesh, const Rigid3d& cam_from_mesh, bool moving = false);
  // Fills the id and 1/z buffers of rows [row_begin, row_end); threads may run disjoint
  // row ranges at once.
  void Rasterize(int row_begin, int row_end);

  const std::vector<ScreenTriangle>& triangles() const { return triangles_; }
  // Index of the visible triangle per pixel, -1 where nothing was drawn (sky).
  const std::vector<int32_t>& ids() const { return ids_; }
  const PinholeCamera& camera() const { return camera_; }

 private:
  void AddClippedTriangle(const Eigen::Vector3d p[3], const Eigen::Vector2d st[3],
                          const SurfaceStyle* style, bool moving);

  PinholeCamera camera_;
  double near_, far_;
  Eigen::Vector3d sun_in_cam_ = Eigen::Vector3d::UnitZ();
  double ambient_ = 0.5;
  std::vector<ScreenTriangle> triangles_;
  std::vector<int32_t> ids_;
  std::vector<double> inv_z_;
  std::vector<Eigen::Vector3d> scratch_;
};

}  // namespace roadscale::synth
