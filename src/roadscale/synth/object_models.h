#pragma once

#include <cstdint>

#include "roadscale/synth/mesh.h"
#include "roadscale/util/random.h"

namespace roadscale::synth {

// Meshes of the things beside and on the road, each in its own frame: x forward (or along
// the road), y left, z up, origin on the ground at the object's centre.

struct CarShape {
  double length = 4.3, width = 1.78, height = 1.45;
};

// A car: body, glazed cabin, roof and four wheels (label car). The road shows between the
// wheels under the body, as it does under real cars.
Mesh MakeCar(const CarShape& shape, const Rgb& paint, uint32_t variant);
// A random car size and paint.
CarShape RandomCarShape(Rng& rng);
Rgb RandomCarPaint(Rng& rng);

// A pedestrian walking along x; `stride_phase` (radians) swings the legs.
Mesh MakePedestrian(double height, const Rgb& clothes, uint32_t variant, double stride_phase);

// A tree: trunk and an irregular crown (label vegetation).
void AddTree(Mesh& mesh, const Eigen::Vector3d& base, double height, double crown_radius,
             uint32_t variant, Rng& rng);
// A street light (label pole) with its arm reaching towards -y of `axes`.
void AddStreetLight(Mesh& mesh, const Eigen::Vector3d& base, const Eigen::Matrix3d& axes,
                    double height);
// A traffic sign: a pole and a panel facing -x of `axes`.
void AddTrafficSign(Mesh& mesh, const Eigen::Vector3d& base, const Eigen::Matrix3d& axes,
                    uint32_t variant);

}  // namespace roadscale::synth
