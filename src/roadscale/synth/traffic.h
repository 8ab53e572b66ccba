#pragma once

#include <vector>

#include "roadscale/geometry/rigid3.h"
#include "roadscale/synth/centre_line.h"
#include "roadscale/synth/mesh.h"
#include "roadscale/synth/object_models.h"
#include "roadscale/synth/road_layout.h"
#include "roadscale/synth/scene_options.h"
#include "roadscale/synth/static_world.h"
#include "roadscale/synth/vehicle_motion.h"
#include "roadscale/util/random.h"

namespace roadscale::synth {

// A road user at one instant: its mesh (in its own frame), where it is, and whether it is
// moving then (a stopped lead car and a standing pedestrian are not).
struct ActorPose {
  const Mesh* mesh = nullptr;
  Rigid3d world_from_mesh = Rigid3d::Identity();
  bool moving = true;
};

// Moving cars and pedestrians on their own trajectories along the road: a lead car that
// replays the ego's motion a moment later (so it stops when the ego stops), cars in the
// other same-direction lanes, oncoming cars, cars that overtake the ego (pulling out into
// the next lane and back) and pedestrians on the sidewalks.
class Traffic {
 public:
  Traffic(const SceneOptions& options, const CentreLine& line, const LateralLayout& layout,
          const VehicleMotion& ego, double duration, double u_begin, double u_end,
          const Eigen::Vector3d& sun, Rng rng);

  // The actors near [u_min, u_max] at `time`. Pedestrian meshes are built into `scratch`
  // (which must outlive the poses); ground shadows of the cars are appended to `shadows`.
  void Collect(double time, double u_min, double u_max, std::vector<ActorPose>* poses,
               std::vector<Mesh>* scratch, std::vector<GroundShadow>* shadows) const;

 private:
  enum class Kind { kLead, kFree, kOncoming, kOvertaking };
  struct Car {
    Kind kind = Kind::kFree;
    CarShape shape;
    Mesh mesh;
    double u0 = 0.0, t0 = 0.0, speed = 0.0, lane = 0.0, pass_lane = 0.0, gap = 0.0;
  };
  struct Walker {
    double u0 = 0.0, l = 0.0, speed = 0.0, height = 1.75;
    Rgb clothes;
    uint32_t variant = 0;
  };
  // Arc position, lateral offset and direction (+1 with the ego, -1 against) of a car.
  void CarPlace(const Car& car, double time, double* u, double* l, double* direction,
                double* yaw) const;

  const CentreLine& line_;
  const VehicleMotion& ego_;
  Eigen::Vector3d sun_;
  bool shadows_ = true;
  double kerb_height_ = 0.15;
  double lead_delay_ = 1.0;
  double lead_gap_max_ = 30.0;
  std::vector<Car> cars_;
  std::vector<Walker> walkers_;
};

}  // namespace roadscale::synth
