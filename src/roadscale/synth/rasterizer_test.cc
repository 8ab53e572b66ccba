#include "roadscale/synth/rasterizer.h"

#include <cmath>

#include <gtest/gtest.h>

namespace roadscale::synth {
namespace {

PinholeCamera SmallCamera() {
  PinholeCamera camera;
  camera.fx = camera.fy = 100.0;
  camera.cx = 79.5;
  camera.cy = 39.5;
  camera.width = 160;
  camera.height = 80;
  return camera;
}

double InvZ(const ScreenTriangle& t, int x, int y) {
  return t.inv_z[0] * x + t.inv_z[1] * y + t.inv_z[2];
}

TEST(Rasterizer, WallFacingTheCameraCoversEveryPixelAtItsDepth) {
  const PinholeCamera camera = SmallCamera();
  Rasterizer rasterizer(camera, 0.1, 100.0);
  Mesh mesh;
  SurfaceStyle style;
  // A quad at z = 10 much larger than the view; its diagonal crosses pixel centres.
  mesh.AddQuad({-20.0, -20.0, 10.0}, {-20.0, 20.0, 10.0}, {20.0, 20.0, 10.0}, {20.0, -20.0, 10.0},
               {0, 0}, {0, 40}, {40, 40}, {40, 0}, style);
  rasterizer.BeginFrame(Eigen::Vector3d(0.0, 0.0, -1.0), 0.5);
  rasterizer.AddMesh(mesh, Rigid3d::Identity());
  rasterizer.Rasterize(0, camera.height);
  ASSERT_EQ(rasterizer.triangles().size(), 2u);
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const int32_t id = rasterizer.ids()[y * camera.width + x];
      ASSERT_GE(id, 0) << x << "," << y;
      EXPECT_NEAR(1.0 / InvZ(rasterizer.triangles()[id], x, y), 10.0, 1e-9);
    }
  }
  // Texture coordinates are perspective-correct: s = X + 20 at the pixel's ray.
  const ScreenTriangle& t = rasterizer.triangles()[rasterizer.ids()[5 * camera.width + 7]];
  const double z = 1.0 / InvZ(t, 7, 5);
  const double s = (t.s_z[0] * 7 + t.s_z[1] * 5 + t.s_z[2]) * z;
  EXPECT_NEAR(s, (7 - camera.cx) / camera.fx * 10.0 + 20.0, 1e-9);
  // Lit from straight ahead (the sun behind the camera), the wall gets full light.
  EXPECT_NEAR(t.light, 1.0, 1e-6);
}

TEST(Rasterizer, GroundThroughTheNearPlaneIsClippedAndExact) {
  const PinholeCamera camera = SmallCamera();
  Rasterizer rasterizer(camera, 0.1, 1000.0);
  Mesh mesh;
  SurfaceStyle style;
  const double h = 1.65;  // the ground plane y = h in the camera frame, passing under it
  mesh.AddQuad({-50.0, h, -5.0}, {-50.0, h, 500.0}, {50.0, h, 500.0}, {50.0, h, -5.0}, {0, 0},
               {0, 1}, {1, 1}, {1, 0}, style);
  rasterizer.BeginFrame(Eigen::Vector3d(0.0, -1.0, 0.0), 0.5);
  rasterizer.AddMesh(mesh, Rigid3d::Identity());
  rasterizer.Rasterize(0, 40);
  rasterizer.Rasterize(40, camera.height);
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const int32_t id = rasterizer.ids()[y * camera.width + x];
      const double ray_y = (y - camera.cy) / camera.fy;
      // Below the horizon the ground is at z = h / ray_y (near enough to fill the width).
      if (ray_y > h / 60.0) {
        ASSERT_GE(id, 0) << x << "," << y;
        EXPECT_NEAR(1.0 / InvZ(rasterizer.triangles()[id], x, y), h / ray_y, 1e-9);
      } else if (ray_y < 0.0) {
        EXPECT_EQ(id, -1);
      }
    }
  }
}

TEST(Rasterizer, NearerTriangleWinsWhateverTheOrder) {
  const PinholeCamera camera = SmallCamera();
  Mesh near_mesh, far_mesh;
  SurfaceStyle style;
  near_mesh.AddQuad({-1.0, -1.0, 5.0}, {1.0, -1.0, 5.0}, {1.0, 1.0, 5.0}, {-1.0, 1.0, 5.0}, {0, 0},
                    {1, 0}, {1, 1}, {0, 1}, style);
  far_mesh.AddQuad({-9.0, -9.0, 8.0}, {9.0, -9.0, 8.0}, {9.0, 9.0, 8.0}, {-9.0, 9.0, 8.0}, {0, 0},
                   {1, 0}, {1, 1}, {0, 1}, style);
  for (int order = 0; order < 2; ++order) {
    Rasterizer rasterizer(camera, 0.1, 100.0);
    rasterizer.BeginFrame(Eigen::Vector3d::UnitZ(), 0.5);
    rasterizer.AddMesh(order == 0 ? near_mesh : far_mesh, Rigid3d::Identity());
    rasterizer.AddMesh(order == 0 ? far_mesh : near_mesh, Rigid3d::Identity());
    rasterizer.Rasterize(0, camera.height);
    const int centre = 40 * camera.width + 80;
    const ScreenTriangle& t = rasterizer.triangles()[rasterizer.ids()[centre]];
    EXPECT_NEAR(1.0 / InvZ(t, 80, 40), 5.0, 1e-9);
    const int corner = 2 * camera.width + 2;
    const ScreenTriangle& u = rasterizer.triangles()[rasterizer.ids()[corner]];
    EXPECT_NEAR(1.0 / InvZ(u, 2, 2), 8.0, 1e-9);
  }
}

TEST(Rasterizer, CullsWhatIsBehindOrBeside) {
  const PinholeCamera camera = SmallCamera();
  Rasterizer rasterizer(camera, 0.1, 100.0);
  Mesh mesh;
  SurfaceStyle style;
  mesh.AddQuad({-1.0, -1.0, -5.0}, {1.0, -1.0, -5.0}, {1.0, 1.0, -5.0}, {-1.0, 1.0, -5.0}, {0, 0},
               {1, 0}, {1, 1}, {0, 1}, style);  // behind
  mesh.AddQuad({50.0, -1.0, 5.0}, {52.0, -1.0, 5.0}, {52.0, 1.0, 5.0}, {50.0, 1.0, 5.0}, {0, 0},
               {1, 0}, {1, 1}, {0, 1}, style);  // right of the view
  mesh.AddQuad({-1.0, -1.0, 150.0}, {1.0, -1.0, 150.0}, {1.0, 1.0, 150.0}, {-1.0, 1.0, 150.0},
               {0, 0}, {1, 0}, {1, 1}, {0, 1}, style);  // too far
  rasterizer.BeginFrame(Eigen::Vector3d::UnitZ(), 0.5);
  rasterizer.AddMesh(mesh, Rigid3d::Identity());
  EXPECT_TRUE(rasterizer.triangles().empty());
}

}  // namespace
}  // namespace roadscale::synth
