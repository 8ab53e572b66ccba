#include "roadscale/synth/vehicle_motion.h"

#include <algorithm>
#include <cmath>

#include "roadscale/geometry/angles.h"

namespace roadscale::synth {
namespace {

// Extra planned time beyond the last frame: the lead car replays the ego's motion ahead.
constexpr double kMarginSeconds = 30.0;

}  // namespace

VehicleMotion::VehicleMotion(const VehicleOptions& options, double duration, Rng rng)
    : options_(options), duration_(duration) {
  const double total = duration + kMarginSeconds;
  const int steps = static_cast<int>(std::ceil(total / step_)) + 1;
  position_.resize(steps);
  speed_.resize(steps);
  acceleration_.resize(steps);

  // Phases: cruise at a target speed for a while, then maybe stop for a while.
  double speed = options.initial_speed;
  double position = options.start_position;
  double phase_end = 0.0;
  bool stopping = false;
  double target = speed;
  double stop_hold = 0.0;  // seconds to stay still once stopped
  for (int i = 0; i < steps; ++i) {
    const double time = i * step_;
    if (time >= phase_end && !(stopping && speed > 0.0)) {
      if (!stopping && rng.Bernoulli(options.stop_probability) && i > 0) {
        stopping = true;
        stop_hold = rng.Uniform(options.stop_min_s, options.stop_max_s);
        phase_end = 1e300;  // ends when the hold is over
      } else {
        stopping = false;
        target = rng.Uniform(options.speed_min, options.speed_max);
        phase_end = time + rng.Uniform(options.cruise_min_s, options.cruise_max_s);
      }
    }
    if (stopping && speed == 0.0) {
      stop_hold -= step_;
      if (stop_hold <= 0.0) phase_end = time;  // next step starts a new phase
    }
    const double goal = stopping ? 0.0 : target;
    double acceleration = 0.0;
    if (goal > speed) {
      acceleration = std::min(options.acceleration, (goal - speed) / step_);
    } else if (goal < speed) {
      acceleration = -std::min(options.deceleration, (speed - goal) / step_);
    }
    position_[i] = position;
    speed_[i] = speed;
    acceleration_[i] = acceleration;
    // Exact kinematics over the step with constant acceleration.
    const double next_speed = std::max(0.0, speed + acceleration * step_);
    position += 0.5 * (speed + next_speed) * step_;
    speed = next_speed;
    if (speed < 1e-9) speed = 0.0;
  }

  pitch_phase_ = rng.Uniform(0.0, 2.0 * M_PI);
  roll_phase_ = rng.Uniform(0.0, 2.0 * M_PI);
  if (options.bumps_per_km > 0.0) {
    const double end = position_.back() + 100.0;
    double u = options.start_position + rng.Uniform(0.0, 1000.0 / options.bumps_per_km);
    while (u < end) {
      // One draw a statement (traffic.cc).
      const double amplitude = options.bump_pitch_deg * kRadiansPerDegree * rng.Uniform(0.5, 1.0);
      bumps_.push_back({u, rng.Bernoulli(0.5) ? amplitude : -amplitude});
      u += rng.Uniform(0.3, 1.7) * 1000.0 / options.bumps_per_km;
    }
  }
}

double VehicleMotion::Suspension(double time, double position, double speed, double acceleration,
                                 bool roll) const {
  // Everything scales with speed, so a stopped car does not rock.
  const double gain = std::min(1.0, speed / options_.suspension_speed);
  if (gain <= 0.0) return 0.0;
  if (roll) {
    return gain * options_.roll_amplitude_deg * kRadiansPerDegree *
           std::sin(2.0 * M_PI * options_.roll_frequency_hz * time + roll_phase_);
  }
  double pitch =
      gain * options_.pitch_amplitude_deg * kRadiansPerDegree *
      (std::sin(2.0 * M_PI * options_.pitch_frequency_hz * time + pitch_phase_) +
       0.3 * std::sin(2.0 * M_PI * 2.3 * options_.pitch_frequency_hz * time + 2.0 * pitch_phase_));
  // Braking dips the nose (the camera looks down), accelerating lifts it.
  pitch += options_.pitch_per_acceleration_deg * kRadiansPerDegree * acceleration;
  // Bumps passed at speed ring down in time.
  for (const Bump& bump : bumps_) {
    if (bump.position > position) break;
    const double since = (position - bump.position) / std::max(speed, 0.5);
    if (since > 4.0) continue;
    pitch += gain * bump.amplitude * std::exp(-options_.bump_damping * since) *
             std::sin(2.0 * M_PI * options_.bump_frequency_hz * since + 0.5 * M_PI);
  }
  return pitch;
}

double VehicleMotion::PositionAt(double time) const {
  const double x = std::max(0.0, time) / step_;
  const size_t i = std::min(static_cast<size_t>(x), position_.size() - 2);
  const double a = std::min(1.0, x - static_cast<double>(i));
  // Linear within a 10 ms step: off by at most a * step^2 / 8 (tens of micrometres) and
  // never running backwards.
  return position_[i] + a * (position_[i + 1] - position_[i]);
}

VehicleState VehicleMotion::StateAt(double time) const {
  VehicleState state;
  state.time = time;
  const double x = std::max(0.0, time) / step_;
  const size_t i = std::min(static_cast<size_t>(std::llround(x)), position_.size() - 1);
  if (std::abs(x - static_cast<double>(i)) < 1e-6) {
    state.position = position_[i];
    state.speed = speed_[i];
    state.acceleration = acceleration_[i];
  } else {
    const size_t j = std::min(static_cast<size_t>(x), position_.size() - 2);
    state.position = PositionAt(time);
    state.speed = speed_[j];
    state.acceleration = acceleration_[j];
  }
  state.pitch = options_.camera_pitch_deg * kRadiansPerDegree +
                Suspension(time, state.position, state.speed, state.acceleration, false);
  state.roll = options_.camera_roll_deg * kRadiansPerDegree +
               Suspension(time, state.position, state.speed, state.acceleration, true);
  return state;
}

Rigid3d VehicleMotion::WorldFromCam(const CentreLine& line, const VehicleState& state, double h0,
                                    double camera_ahead) {
  const RoadFrame frame = line.FrameAt(state.position);
  Eigen::Matrix3d base;
  const Eigen::Vector3d z = frame.tangent;
  const Eigen::Vector3d y = -frame.normal;
  base.col(0) = y.cross(z);
  base.col(1) = y;
  base.col(2) = z;
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(state.pitch, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(state.roll, Eigen::Vector3d::UnitZ()))
                                   .toRotationMatrix();
  return MakeRigid3d(base * turn, frame.point + h0 * frame.normal + camera_ahead * frame.tangent);
}

}  // namespace roadscale::synth
