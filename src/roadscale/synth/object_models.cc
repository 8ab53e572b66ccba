#include "roadscale/synth/object_models.h"

#include <cmath>
#include <vector>

namespace roadscale::synth {
namespace {

SurfaceStyle Style(Material material, uint8_t label_id, uint32_t variant, const Rgb& tint,
                   bool two_sided = false) {
  SurfaceStyle style;
  style.material = material;
  style.label = label_id;
  style.variant = variant;
  style.tint = tint;
  style.two_sided = two_sided;
  return style;
}

}  // namespace

CarShape RandomCarShape(Rng& rng) {
  CarShape shape;
  const int kind = rng.UniformInt(0, 9);
  if (kind < 6) {  // saloon / hatchback
    shape.length = rng.Uniform(3.8, 4.7);
    shape.width = rng.Uniform(1.7, 1.85);
    shape.height = rng.Uniform(1.4, 1.55);
  } else if (kind < 9) {  // estate / SUV
    shape.length = rng.Uniform(4.4, 4.9);
    shape.width = rng.Uniform(1.8, 1.95);
    shape.height = rng.Uniform(1.6, 1.8);
  } else {  // van
    shape.length = rng.Uniform(4.8, 5.6);
    shape.width = rng.Uniform(1.9, 2.05);
    shape.height = rng.Uniform(1.9, 2.3);
  }
  return shape;
}

Rgb RandomCarPaint(Rng& rng) {
  static const Rgb kPaints[] = {{0.85f, 0.85f, 0.85f}, {0.1f, 0.1f, 0.11f},  {0.55f, 0.56f, 0.58f},
                                {0.35f, 0.36f, 0.38f}, {0.55f, 0.1f, 0.08f}, {0.12f, 0.2f, 0.45f},
                                {0.7f, 0.7f, 0.72f},   {0.2f, 0.3f, 0.22f},  {0.9f, 0.88f, 0.82f},
                                {0.45f, 0.4f, 0.3f}};
  const Rgb& base = kPaints[rng.UniformInt(0, 9)];
  const float k = static_cast<float>(rng.Uniform(0.9, 1.1));
  return {base.r * k, base.g * k, base.b * k};
}

Mesh MakeCar(const CarShape& shape, const Rgb& paint, uint32_t variant) {
  Mesh mesh;
  const Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  const SurfaceStyle body = Style(Material::kCarPaint, label::kCar, variant, paint);
  const SurfaceStyle glass = Style(Material::kCarGlass, label::kCar, variant,
                                   {paint.r * 0.8f, paint.g * 0.8f, paint.b * 0.8f});
  const SurfaceStyle tyre = Style(Material::kTyre, label::kCar, variant, {0.07f, 0.07f, 0.07f});
  const SurfaceStyle dark = Style(Material::kMetal, label::kCar, variant, {0.05f, 0.05f, 0.05f});
  const SurfaceStyle head = Style(Material::kMetal, label::kCar, variant, {0.85f, 0.85f, 0.8f});
  const SurfaceStyle tail = Style(Material::kMetal, label::kCar, variant, {0.55f, 0.06f, 0.05f});
  const SurfaceStyle plate = Style(Material::kMetal, label::kCar, variant, {0.9f, 0.9f, 0.88f});
  const double length = shape.length, width = shape.width, height = shape.height;
  const double clearance = 0.28;
  const double body_top = std::min(0.95, 0.55 * height);
  // Dark underbody between the wheels, slightly inset.
  mesh.AddBox({0.0, 0.0, 0.18}, axes, length - 0.9, width - 0.3, clearance - 0.18, &dark, nullptr);
  mesh.AddBox({0.0, 0.0, clearance}, axes, length, width, body_top - clearance, &body, &body);
  // Cabin: a frustum with a raked windscreen and rear window, glazed, with a painted roof.
  const double x0 = -0.45 * length, x1 = 0.22 * length;           // cabin foot, back and front
  const double t0 = x0 + 0.12 * length, t1 = x1 - 0.22 * length;  // roof, back and front
  const double wb = 0.5 * width - 0.06, wt = 0.5 * width - 0.2;
  const double z0 = body_top, z1 = height;
  const Eigen::Vector3d b[4] = {{x0, -wb, z0}, {x1, -wb, z0}, {x1, wb, z0}, {x0, wb, z0}};
  const Eigen::Vector3d t[4] = {{t0, -wt, z1}, {t1, -wt, z1}, {t1, wt, z1}, {t0, wt, z1}};
  const double rise = z1 - z0;
  // The windscreen and rear window have no pillars: their frame colour is the glass's.
  const SurfaceStyle screen =
      Style(Material::kCarGlass, label::kCar, variant, {0.12f, 0.13f, 0.15f});
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 1) % 4;
    const double run = (b[j] - b[k]).norm();
    mesh.AddQuad(b[k], b[j], t[j], t[k], {0.0, 0.0}, {run, 0.0}, {run, rise}, {0.0, rise},
                 k % 2 == 0 ? glass : screen);
  }
  mesh.AddQuad(t[0], t[1], t[2], t[3], {0.0, 0.0}, {t1 - t0, 0.0}, {t1 - t0, 2 * wt}, {0.0, 2 * wt},
               body);
  // Lights and number plates, standing 1 cm proud of the body.
  const double light_z = body_top - 0.2;
  for (int side = -1; side <= 1; side += 2) {
    const double y = side * (0.5 * width - 0.27);
    mesh.AddBox({0.5 * length + 0.005, y, light_z}, axes, 0.02, 0.3, 0.12, &head, nullptr);
    mesh.AddBox({-0.5 * length - 0.005, y, light_z}, axes, 0.02, 0.28, 0.14, &tail, nullptr);
  }
  for (int end = -1; end <= 1; end += 2) {
    mesh.AddBox({end * (0.5 * length + 0.005), 0.0, clearance + 0.1}, axes, 0.02, 0.52, 0.11,
                &plate, nullptr);
  }
  const double wheel = 0.62;
  for (int i = 0; i < 4; ++i) {
    const double x = (i < 2 ? 1.0 : -1.0) * (0.5 * length - 0.75);
    const double y = (i % 2 == 0 ? 1.0 : -1.0) * (0.5 * width - 0.14);
    mesh.AddBox({x, y, 0.0}, axes, wheel, 0.24, wheel, &tyre, &tyre);
  }
  return mesh;
}

Mesh MakePedestrian(double height, const Rgb& clothes, uint32_t variant, double stride_phase) {
  Mesh mesh;
  const SurfaceStyle cloth = Style(Material::kCloth, label::kPerson, variant, clothes);
  const SurfaceStyle trousers =
      Style(Material::kCloth, label::kPerson, variant + 1, {0.15f, 0.15f, 0.2f});
  const SurfaceStyle skin = Style(Material::kSkin, label::kPerson, variant, {0.62f, 0.5f, 0.42f});
  const double leg = 0.47 * height;
  const double torso = 0.33 * height;
  const double head = 0.13 * height;
  const double swing = 0.35 * std::sin(stride_phase);
  for (int side = -1; side <= 1; side += 2) {
    // A leg swings about the hip: tilt the box axes.
    const double angle = side * swing;
    Eigen::Matrix3d axes;
    axes.col(0) = Eigen::Vector3d(std::cos(angle), 0.0, std::sin(angle));
    axes.col(1) = Eigen::Vector3d::UnitY();
    axes.col(2) = Eigen::Vector3d(-std::sin(angle), 0.0, std::cos(angle));
    const Eigen::Vector3d hip(0.0, 0.1 * side, leg);
    const Eigen::Vector3d foot = hip - leg * axes.col(2);
    mesh.AddBox(foot, axes, 0.16, 0.14, leg, &trousers, nullptr);
  }
  const Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  mesh.AddBox({0.0, 0.0, leg}, axes, 0.26, 0.42, torso, &cloth, &cloth);
  mesh.AddBox({0.0, 0.0, leg + torso + 0.02}, axes, 0.2, 0.18, head, &skin, &skin);
  return mesh;
}

void AddTree(Mesh& mesh, const Eigen::Vector3d& base, double height, double crown_radius,
             uint32_t variant, Rng& rng) {
  const SurfaceStyle bark =
      Style(Material::kBark, label::kVegetation, variant, {0.22f, 0.2f, 0.17f});
  const SurfaceStyle leaves =
      Style(Material::kFoliage, label::kVegetation, variant,
            {static_cast<float>(rng.Uniform(0.3, 0.4)), static_cast<float>(rng.Uniform(0.4, 0.52)),
             static_cast<float>(rng.Uniform(0.18, 0.26))});
  const double trunk_height = height - 1.4 * crown_radius;
  mesh.AddBox(base - Eigen::Vector3d(0.0, 0.0, 0.3), Eigen::Matrix3d::Identity(), 0.3, 0.3,
              trunk_height + 0.3 + 0.5 * crown_radius, &bark, nullptr);
  // Crown: a lumpy ellipsoid, latitude rings x longitude segments.
  const int rings = 6, segments = 10;
  const Eigen::Vector3d centre = base + Eigen::Vector3d(0.0, 0.0, height - crown_radius);
  std::vector<Eigen::Vector3d> points((rings + 1) * segments);
  for (int r = 0; r <= rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int k = 0; k < segments; ++k) {
      const double phi = 2.0 * M_PI * k / segments;
      const double lump = (r == 0 || r == rings) ? 1.0 : rng.Uniform(0.75, 1.15);
      const double radius = crown_radius * lump;
      points[r * segments + k] =
          centre + Eigen::Vector3d(radius * std::sin(theta) * std::cos(phi),
                                   radius * std::sin(theta) * std::sin(phi),
                                   0.9 * crown_radius * lump * std::cos(theta));
    }
  }
  const double circumference = 2.0 * M_PI * crown_radius;
  for (int r = 0; r < rings; ++r) {
    for (int k = 0; k < segments; ++k) {
      const int k1 = (k + 1) % segments;
      const double s0 = circumference * k / segments;
      const double s1 = circumference * (k + 1) / segments;
      const double t0 = crown_radius * M_PI * (rings - r) / rings;
      const double t1 = crown_radius * M_PI * (rings - r - 1) / rings;
      // Counter-clockwise seen from outside.
      mesh.AddQuad(points[r * segments + k], points[(r + 1) * segments + k],
                   points[(r + 1) * segments + k1], points[r * segments + k1], {s0, t0}, {s0, t1},
                   {s1, t1}, {s1, t0}, leaves);
    }
  }
}

void AddStreetLight(Mesh& mesh, const Eigen::Vector3d& base, const Eigen::Matrix3d& axes,
                    double height) {
  const SurfaceStyle metal = Style(Material::kMetal, label::kPole, 0, {0.42f, 0.43f, 0.45f});
  mesh.AddBox(base - 0.3 * axes.col(2), axes, 0.16, 0.16, height + 0.3, &metal, &metal);
  const double arm = 1.6;
  mesh.AddBox(base + (height - 0.12) * axes.col(2) - 0.5 * arm * axes.col(1), axes, 0.1, arm, 0.1,
              &metal, &metal);
  mesh.AddBox(base + (height - 0.25) * axes.col(2) - (arm - 0.2) * axes.col(1), axes, 0.25, 0.5,
              0.16, &metal, &metal);
}

void AddTrafficSign(Mesh& mesh, const Eigen::Vector3d& base, const Eigen::Matrix3d& axes,
                    uint32_t variant) {
  const SurfaceStyle metal = Style(Material::kMetal, label::kPole, 0, {0.5f, 0.5f, 0.52f});
  const double height = 2.6;
  mesh.AddBox(base - 0.3 * axes.col(2), axes, 0.08, 0.08, height + 0.3, &metal, &metal);
  static const Rgb kColours[] = {{0.85f, 0.85f, 0.85f}, {0.2f, 0.3f, 0.7f}, {0.85f, 0.75f, 0.1f}};
  const SurfaceStyle panel =
      Style(Material::kSign, label::kTrafficSign, variant, kColours[variant % 3], true);
  // A square panel facing -x (towards oncoming drivers when x points along the road).
  const Eigen::Vector3d centre = base + (height + 0.05) * axes.col(2) - 0.06 * axes.col(0);
  const Eigen::Vector3d y = 0.3 * axes.col(1), z = 0.3 * axes.col(2);
  mesh.AddQuad(centre + y - z, centre - y - z, centre - y + z, centre + y + z, {0.0, 0.0},
               {0.6, 0.0}, {0.6, 0.6}, {0.0, 0.6}, panel);
}

}  // namespace roadscale::synth
