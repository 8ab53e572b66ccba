#include "roadscale/synth/traffic.h"

#include <algorithm>
#include <cmath>

#include "roadscale/synth/colour_math.h"

namespace roadscale::synth {
namespace {}  // namespace

Traffic::Traffic(const SceneOptions& options, const CentreLine& line, const LateralLayout& layout,
                 const VehicleMotion& ego, double duration, double u_begin, double u_end,
                 const Eigen::Vector3d& sun, Rng rng)
    : line_(line),
      ego_(ego),
      sun_(sun),
      shadows_(options.texture.shadows),
      kerb_height_(options.road.kerb_height) {
  const TrafficOptions& traffic = options.traffic;
  lead_gap_max_ = traffic.lead_gap_max;
  auto make_car = [&](Kind kind) {
    Car car;
    car.kind = kind;
    car.shape = RandomCarShape(rng);
    // One draw a statement: the order of a call's arguments is the compiler's, and a seed
    // must give the same scene with every compiler.
    const auto variant = static_cast<uint32_t>(rng.NextU64());
    const Rgb paint = RandomCarPaint(rng);
    car.mesh = MakeCar(car.shape, paint, variant);
    return car;
  };
  const double span = u_end - u_begin;
  if (traffic.lead_car) {
    Car car = make_car(Kind::kLead);
    car.gap = rng.Uniform(traffic.lead_gap_min, traffic.lead_gap_max) + 0.5 * car.shape.length;
    cars_.push_back(std::move(car));
  }
  // Free cars: spread over the road and over the time they take to cross it.
  for (size_t k = 1; k < layout.same_lanes.size(); ++k) {
    const int count = static_cast<int>(std::round(traffic.same_direction_per_km * span / 1000.0));
    for (int i = 0; i < count; ++i) {
      Car car = make_car(Kind::kFree);
      car.speed = rng.Uniform(traffic.car_speed_min, traffic.car_speed_max);
      car.u0 = rng.Uniform(u_begin - car.speed * duration, u_end);
      car.lane = layout.same_lanes[k];
      cars_.push_back(std::move(car));
    }
  }
  for (const double lane : layout.opposite_lanes) {
    const double per_lane = traffic.oncoming_per_km / layout.opposite_lanes.size();
    const int count = static_cast<int>(std::round(per_lane * span / 1000.0));
    for (int i = 0; i < count; ++i) {
      Car car = make_car(Kind::kOncoming);
      car.speed = rng.Uniform(traffic.car_speed_min, traffic.car_speed_max);
      car.u0 = rng.Uniform(u_begin, u_end + car.speed * duration);
      car.lane = lane;
      cars_.push_back(std::move(car));
    }
  }
  // Overtakers: pass the ego in the next lane to the left (the oncoming lane on a
  // two-lane road) and return to the ego lane well ahead of the lead car.
  if (traffic.overtaking_per_km > 0.0 &&
      (layout.same_lanes.size() > 1 || !layout.opposite_lanes.empty())) {
    const double pass_lane =
        layout.same_lanes.size() > 1 ? layout.same_lanes[1] : layout.opposite_lanes.front();
    const double distance = ego.PositionAt(duration) - ego.PositionAt(0.0);
    const int count = static_cast<int>(
        std::round(traffic.overtaking_per_km * std::max(distance, 200.0) / 1000.0));
    for (int i = 0; i < count; ++i) {
      Car car = make_car(Kind::kOvertaking);
      // Early enough that the pass is seen.
      car.t0 = rng.Uniform(0.0, std::max(0.0, duration - 6.0));
      const double ego_speed = (ego.PositionAt(car.t0 + 1.0) - ego.PositionAt(car.t0));
      car.speed = ego_speed + rng.Uniform(4.0, 8.0);
      car.u0 = ego.PositionAt(car.t0) - 30.0;
      car.lane = 0.0;
      car.pass_lane = pass_lane;
      cars_.push_back(std::move(car));
    }
  }
  // Pedestrians on the sidewalks: most walk, some stand.
  if (options.road.sidewalk_width >= 1.5 && traffic.pedestrians_per_100m > 0.0) {
    const int count = static_cast<int>(std::round(traffic.pedestrians_per_100m * span / 100.0));
    static const Rgb kClothes[] = {{0.15f, 0.15f, 0.18f}, {0.6f, 0.1f, 0.1f},
                                   {0.2f, 0.3f, 0.6f},    {0.8f, 0.8f, 0.75f},
                                   {0.4f, 0.35f, 0.25f},  {0.3f, 0.45f, 0.3f}};
    for (int i = 0; i < count; ++i) {
      Walker walker;
      const int side = rng.Bernoulli(0.5) ? 1 : -1;
      const double edge = side > 0 ? layout.left_edge : layout.right_edge;
      walker.l = edge + side * rng.Uniform(0.8, options.road.sidewalk_width - 0.4);
      walker.u0 = rng.Uniform(u_begin, u_end);
      walker.speed = 0.0;
      if (rng.Bernoulli(0.75)) {
        const double pace = rng.Uniform(0.9, 1.6);
        walker.speed = rng.Bernoulli(0.5) ? pace : -pace;
      }
      walker.height = rng.Uniform(1.55, 1.9);
      walker.clothes = kClothes[rng.UniformInt(0, 5)];
      walker.variant = static_cast<uint32_t>(rng.NextU64());
      walkers_.push_back(walker);
    }
  }
}

void Traffic::CarPlace(const Car& car, double time, double* u, double* l, double* direction,
                       double* yaw) const {
  *yaw = 0.0;
  *direction = 1.0;
  *l = car.lane;
  switch (car.kind) {
    case Kind::kLead:
      *u = ego_.PositionAt(time + lead_delay_) + car.gap;
      break;
    case Kind::kFree:
      *u = car.u0 + car.speed * time;
      break;
    case Kind::kOncoming:
      *u = car.u0 - car.speed * time;
      *direction = -1.0;
      break;
    case Kind::kOvertaking: {
      *u = car.u0 + car.speed * (time - car.t0);
      // Pull out behind the ego, return ahead of the lead car.
      auto lateral = [&](double uu) {
        const double ahead = uu - ego_.PositionAt(time);
        return car.pass_lane * SmoothStep(-28.0, -12.0, ahead) *
               (1.0 - SmoothStep(lead_gap_max_ + 10.0, lead_gap_max_ + 25.0, ahead));
      };
      *l = lateral(*u);
      *yaw = std::atan2(lateral(*u + 0.5) - lateral(*u - 0.5), 1.0);
      break;
    }
  }
}

void Traffic::Collect(double time, double u_min, double u_max, std::vector<ActorPose>* poses,
                      std::vector<Mesh>* scratch, std::vector<GroundShadow>* shadows) const {
  for (const Car& car : cars_) {
    double u, l, direction, yaw;
    CarPlace(car, time, &u, &l, &direction, &yaw);
    if (u < u_min - car.shape.length || u > u_max + car.shape.length) continue;
    const RoadFrame frame = line_.FrameAt(u);
    const Eigen::Vector3d forward =
        direction * (std::cos(yaw) * frame.tangent + std::sin(yaw) * frame.lateral);
    Eigen::Matrix3d axes;
    axes.col(0) = forward;
    axes.col(2) = frame.normal;
    axes.col(1) = frame.normal.cross(forward);
    ActorPose pose;
    pose.mesh = &car.mesh;
    pose.world_from_mesh = MakeRigid3d(axes, line_.SurfacePoint(frame, l));
    // The lead car replays the ego's motion: it stands when the ego stood.
    pose.moving = car.kind != Kind::kLead || ego_.StateAt(time + lead_delay_).speed > 0.0;
    poses->push_back(pose);
    if (shadows_) {
      const Eigen::Vector2d offset = ShadowOffset(line_, u, 0.8 * car.shape.height, sun_);
      const double half_l = 0.5 * car.shape.length, half_w = 0.5 * car.shape.width;
      shadows->push_back(
          {u - half_l + std::min(0.0, offset.x()), u + half_l + std::max(0.0, offset.x()),
           l - half_w + std::min(0.0, offset.y()), l + half_w + std::max(0.0, offset.y()), 0.8f});
    }
  }
  // Reserve first: the poses keep pointers into `scratch`.
  size_t needed = scratch->size();
  for (const Walker& walker : walkers_) {
    const double u = walker.u0 + walker.speed * time;
    if (u >= u_min - 2.0 && u <= u_max + 2.0) ++needed;
  }
  scratch->reserve(needed);
  for (const Walker& walker : walkers_) {
    const double u = walker.u0 + walker.speed * time;
    if (u < u_min - 2.0 || u > u_max + 2.0) continue;
    const double phase = 2.0 * M_PI * std::abs(walker.speed) * time / 1.5;
    scratch->push_back(MakePedestrian(walker.height, walker.clothes, walker.variant, phase));
    const RoadFrame frame = line_.FrameAt(u);
    const double direction = walker.speed < 0.0 ? -1.0 : 1.0;
    Eigen::Matrix3d axes;
    axes.col(0) =
        direction * Eigen::Vector3d(std::cos(frame.heading), std::sin(frame.heading), 0.0);
    axes.col(2) = Eigen::Vector3d::UnitZ();
    axes.col(1) = axes.col(2).cross(axes.col(0));
    ActorPose pose;
    pose.mesh = &scratch->back();
    pose.moving = walker.speed != 0.0;
    pose.world_from_mesh = MakeRigid3d(axes, line_.SurfacePoint(frame, walker.l, kerb_height_));
    poses->push_back(pose);
  }
}

}  // namespace roadscale::synth
