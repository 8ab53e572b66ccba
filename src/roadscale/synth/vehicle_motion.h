#pragma once

#include <vector>

#include "roadscale/geometry/rigid3.h"
#include "roadscale/synth/centre_line.h"
#include "roadscale/synth/scene_options.h"
#include "roadscale/util/random.h"

#include <Eigen/Core>

namespace roadscale::synth {

// The ego vehicle's state at one instant.
struct VehicleState {
  double time = 0.0;          // seconds
  double position = 0.0;      // u on the centre line, metres
  double speed = 0.0;         // m/s
  double acceleration = 0.0;  // m/s^2
  double pitch = 0.0;         // radians, suspension + mounting, positive looks up
  double roll = 0.0;          // radians, about the optical axis
};

// The ego vehicle driving the centre line: a speed profile of cruise phases at random
// speeds and full stops (exactly stationary: position, pitch and roll do not change while
// stopped), integrated on a fine time grid, and suspension pitch/roll.
class VehicleMotion {
 public:
  // Plans the motion for `duration` seconds (plus margin for cars that replay it later).
  VehicleMotion(const VehicleOptions& options, double duration, Rng rng);

  // The state at time t (seconds, >= 0), interpolated on the planning grid; exact at every
  // multiple of the grid step, which divides the frame period of the scenes.
  VehicleState StateAt(double time) const;
  double PositionAt(double time) const;
  double duration() const { return duration_; }

  // The camera pose: h0 above the road along the road normal at the state's position, moved
  // `camera_ahead` metres along the road's tangent there, looking along that tangent, turned
  // by the state's pitch and roll about the camera centre. In a turn, a camera ahead of the
  // point that follows the lane moves off its optical axis (VehicleOptions::camera_ahead).
  static Rigid3d WorldFromCam(const CentreLine& line, const VehicleState& state, double h0,
                              double camera_ahead = 0.0);

 private:
  struct Bump {
    double position, amplitude;
  };
  double Suspension(double time, double position, double speed, double acceleration,
                    bool roll) const;

  VehicleOptions options_;
  double duration_ = 0.0;
  double step_ = 0.01;
  std::vector<double> position_, speed_, acceleration_;
  std::vector<Bump> bumps_;
  double pitch_phase_ = 0.0, roll_phase_ = 0.0;
};

}  // namespace roadscale::synth
