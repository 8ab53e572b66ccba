#include "roadscale/synth/rasterizer.h"

#include <algorithm>
#include <cmath>

namespace roadscale::synth {
namespace {

// Pixel centres exactly on an edge count as inside, with this much slack (pixels), so
// that two triangles sharing an edge leave no crack through rounding.
constexpr double kEdgeSlack = 1e-7;

// Affine function f = a x + b y + c through three screen points.
void AffineThrough(const double x[3], const double y[3], const double f[3], double area2,
                   double out[3]) {
  const double df1 = f[1] - f[0], df2 = f[2] - f[0];
  const double dx1 = x[1] - x[0], dx2 = x[2] - x[0];
  const double dy1 = y[1] - y[0], dy2 = y[2] - y[0];
  out[0] = (df1 * dy2 - df2 * dy1) / area2;
  out[1] = (df2 * dx1 - df1 * dx2) / area2;
  out[2] = f[0] - out[0] * x[0] - out[1] * y[0];
}

}  // namespace

Rasterizer::Rasterizer(const PinholeCamera& camera, double near_distance, double far_distance)
    : camera_(camera), near_(near_distance), far_(far_distance) {
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  ids_.assign(pixels, -1);
  inv_z_.assign(pixels, 0.0);
}

void Rasterizer::BeginFrame(const Eigen::Vector3d& sun_in_cam, double ambient) {
  sun_in_cam_ = sun_in_cam.normalized();
  ambient_ = ambient;
  triangles_.clear();
}

void Rasterizer::AddMesh(const Mesh& mesh, const Rigid3d& cam_from_mesh, bool moving) {
  const Eigen::Matrix3d rotation = cam_from_mesh.linear();
  const Eigen::Vector3d translation = cam_from_mesh.translation();
  scratch_.resize(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    scratch_[i] = rotation * mesh.positions[i] + translation;
  }
  // Frustum side planes through the camera centre (normals pointing out), for culling
  // triangles whose three corners lie outside one of them.
  const double fx = camera_.fx, fy = camera_.fy, cx = camera_.cx, cy = camera_.cy;
  const double w = camera_.width, h = camera_.height;
  const Eigen::Vector3d planes[4] = {{-fx, 0.0, -(cx + 0.5)},
                                     {fx, 0.0, -(w - 0.5 - cx)},
                                     {0.0, -fy, -(cy + 0.5)},
                                     {0.0, fy, -(h - 0.5 - cy)}};
  for (const MeshTriangle& triangle : mesh.triangles) {
    Eigen::Vector3d p[3] = {scratch_[triangle.v[0]], scratch_[triangle.v[1]],
                            scratch_[triangle.v[2]]};
    int behind = 0, beyond = 0;
    for (const Eigen::Vector3d& q : p) {
      behind += q.z() < near_;
      beyond += q.z() > far_;
    }
    if (behind == 3 || beyond == 3) continue;
    bool outside = false;
    for (const Eigen::Vector3d& plane : planes) {
      if (plane.dot(p[0]) > 0.0 && plane.dot(p[1]) > 0.0 && plane.dot(p[2]) > 0.0) {
        outside = true;
        break;
      }
    }
    if (outside) continue;
    Eigen::Vector2d st[3];
    for (int k = 0; k < 3; ++k) st[k] = mesh.texcoords[triangle.v[k]].cast<double>();
    if (behind == 0) {
      AddClippedTriangle(p, st, &triangle.style, moving);
      continue;
    }
    // Sutherland-Hodgman against z = near: a triangle or a quad.
    Eigen::Vector3d poly[4];
    Eigen::Vector2d poly_st[4];
    int count = 0;
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      const bool in_k = p[k].z() >= near_, in_j = p[j].z() >= near_;
      if (in_k) {
        poly[count] = p[k];
        poly_st[count++] = st[k];
      }
      if (in_k != in_j) {
        const double a = (near_ - p[k].z()) / (p[j].z() - p[k].z());
        poly[count] = p[k] + a * (p[j] - p[k]);
        poly[count].z() = near_;
        poly_st[count++] = st[k] + a * (st[j] - st[k]);
      }
    }
    for (int k = 1; k + 1 < count; ++k) {
      const Eigen::Vector3d q[3] = {poly[0], poly[k], poly[k + 1]};
      const Eigen::Vector2d q_st[3] = {poly_st[0], poly_st[k], poly_st[k + 1]};
      AddClippedTriangle(q, q_st, &triangle.style, moving);
    }
  }
}

void Rasterizer::AddClippedTriangle(const Eigen::Vector3d p[3], const Eigen::Vector2d st[3],
                                    const SurfaceStyle* style, bool moving) {
  ScreenTriangle t;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  double s_over_z[3], t_over_z[3];
  for (int k = 0; k < 3; ++k) {
    const double inv = 1.0 / p[k].z();
    t.x[k] = camera_.fx * p[k].x() * inv + camera_.cx;
    t.y[k] = camera_.fy * p[k].y() * inv + camera_.cy;
    s_over_z[k] = st[k].x() * inv;
    t_over_z[k] = st[k].y() * inv;
    xmin = std::min(xmin, t.x[k]);
    xmax = std::max(xmax, t.x[k]);
    ymin = std::min(ymin, t.y[k]);
    ymax = std::max(ymax, t.y[k]);
  }
  // No pixel centre inside the bounding box (or the image): nothing to draw.
  const double x_lo = std::max(0.0, std::ceil(xmin - kEdgeSlack));
  const double x_hi = std::min(camera_.width - 1.0, std::floor(xmax + kEdgeSlack));
  const double y_lo = std::max(0.0, std::ceil(ymin - kEdgeSlack));
  const double y_hi = std::min(camera_.height - 1.0, std::floor(ymax + kEdgeSlack));
  if (x_lo > x_hi || y_lo > y_hi) return;

  const double area2 =
      (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]) - (t.y[2] - t.y[0]) * (t.x[1] - t.x[0]);
  if (std::abs(area2) < 1e-12) return;

  // 1/z from the plane n . X = d through the camera-frame corners: exact at every pixel.
  Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
  const double norm = n.norm();
  if (!(norm > 0.0)) return;
  n /= norm;
  const double d = n.dot(p[0]);
  if (std::abs(d) < 1e-9) return;  // seen edge-on
  t.inv_z[0] = n.x() / (camera_.fx * d);
  t.inv_z[1] = n.y() / (camera_.fy * d);
  t.inv_z[2] = (n.z() - n.x() * camera_.cx / camera_.fx - n.y() * camera_.cy / camera_.fy) / d;
  AffineThrough(t.x, t.y, s_over_z, -area2, t.s_z);
  AffineThrough(t.x, t.y, t_over_z, -area2, t.t_z);

  double cosine = n.dot(sun_in_cam_);
  cosine = style->two_sided ? std::abs(cosine) : std::max(0.0, cosine);
  t.light = static_cast<float>(ambient_ + (1.0 - ambient_) * cosine);
  t.style = style;
  t.moving = moving;
  triangles_.push_back(t);
}

void Rasterizer::Rasterize(int row_begin, int row_end) {
  const int width = camera_.width;
  row_begin = std::max(0, row_begin);
  row_end = std::min(camera_.height, row_end);
  const double far_inv_z = 1.0 / far_;
  for (int y = row_begin; y < row_end; ++y) {
    std::fill(ids_.begin() + static_cast<size_t>(y) * width,
              ids_.begin() + static_cast<size_t>(y + 1) * width, -1);
    std::fill(inv_z_.begin() + static_cast<size_t>(y) * width,
              inv_z_.begin() + static_cast<size_t>(y + 1) * width, far_inv_z);
  }
  const int32_t count = static_cast<int32_t>(triangles_.size());
  for (int32_t id = 0; id < count; ++id) {
    const ScreenTriangle& t = triangles_[id];
    const double ymin = std::min({t.y[0], t.y[1], t.y[2]});
    const double ymax = std::max({t.y[0], t.y[1], t.y[2]});
    const int y0 = std::max(row_begin, static_cast<int>(std::ceil(ymin - kEdgeSlack)));
    const int y1 = std::min(row_end - 1, static_cast<int>(std::floor(ymax + kEdgeSlack)));
    if (y0 > y1) continue;
    const double xmin = std::min({t.x[0], t.x[1], t.x[2]});
    const double xmax = std::max({t.x[0], t.x[1], t.x[2]});
    const double xb0 = std::max(0.0, std::ceil(xmin - kEdgeSlack));
    const double xb1 = std::min(width - 1.0, std::floor(xmax + kEdgeSlack));
    if (xb0 > xb1) continue;

    // Edge functions E = A x + B y + C, positive inside.
    double A[3], B[3], C[3];
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      A[k] = t.y[j] - t.y[k];
      B[k] = -(t.x[j] - t.x[k]);
      C[k] = -A[k] * t.x[k] - B[k] * t.y[k];
    }
    // The opposite corner must be inside edge 0; flip all when the winding says otherwise.
    if (A[0] * t.x[2] + B[0] * t.y[2] + C[0] < 0.0) {
      for (int k = 0; k < 3; ++k) {
        A[k] = -A[k];
        B[k] = -B[k];
        C[k] = -C[k];
      }
    }
    for (int y = y0; y <= y1; ++y) {
      double lo = xb0, hi = xb1;
      bool empty = false;
      for (int k = 0; k < 3; ++k) {
        const double r = B[k] * y + C[k];
        if (A[k] > 0.0) {
          lo = std::max(lo, -r / A[k] - kEdgeSlack);
        } else if (A[k] < 0.0) {
          hi = std::min(hi, -r / A[k] + kEdgeSlack);
        } else if (r < -kEdgeSlack * std::abs(B[k])) {
          empty = true;
        }
      }
      if (empty) continue;
      const int x0 = static_cast<int>(std::ceil(lo));
      const int x1 = static_cast<int>(std::floor(hi));
      if (x0 > x1) continue;
      const size_t row = static_cast<size_t>(y) * width;
      const double base = t.inv_z[1] * y + t.inv_z[2];
      for (int x = x0; x <= x1; ++x) {
        const double iz = t.inv_z[0] * x + base;
        if (iz > inv_z_[row + x]) {
          inv_z_[row + x] = iz;
          ids_[row + x] = id;
        }
      }
    }
  }
}

}  // namespace roadscale::synth
