#include "roadscale/synth/vehicle_motion.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace roadscale::synth {
namespace {

TEST(VehicleMotion, SpeedStaysInItsLimitsAndStopsAreStill) {
  VehicleOptions options;
  options.initial_speed = 0.0;
  options.stop_probability = 0.7;
  const double duration = 120.0;
  const VehicleMotion motion(options, duration, Rng(4));
  double previous_speed = 0.0, previous_position = motion.PositionAt(0.0);
  int stopped = 0;
  for (double t = 0.1; t <= duration; t += 0.1) {
    const VehicleState state = motion.StateAt(t);
    EXPECT_GE(state.speed, 0.0);
    EXPECT_LE(state.speed, options.speed_max + 1e-9);
    const double acceleration = (state.speed - previous_speed) / 0.1;
    EXPECT_LE(acceleration, options.acceleration + 1e-6);
    EXPECT_GE(acceleration, -options.deceleration - 1e-6);
    EXPECT_GE(state.position, previous_position);
    if (state.speed == 0.0 && previous_speed == 0.0) {
      ++stopped;
      EXPECT_EQ(state.position, previous_position);
      EXPECT_EQ(state.pitch, 0.0);
      EXPECT_EQ(state.roll, 0.0);
    }
    previous_speed = state.speed;
    previous_position = state.position;
  }
  EXPECT_GT(stopped, 50);
  // It does drive: about its cruise speeds on average.
  EXPECT_GT(motion.PositionAt(duration) - motion.PositionAt(0.0), 200.0);
}

TEST(VehicleMotion, CameraIsH0AboveTheRoadAlongItsNormal) {
  const CentreLine line({{50.0, 0.0, 0.0, 0.0, 10.0}, {60.0, 1.0 / 25.0, 0.05, 0.03, 20.0}});
  VehicleState state;
  state.position = 80.0;
  state.pitch = 0.02;
  state.roll = -0.01;
  const Rigid3d world_from_cam = VehicleMotion::WorldFromCam(line, state, 1.65);
  const RoadFrame frame = line.FrameAt(80.0);
  EXPECT_NEAR((world_from_cam.translation() - (frame.point + 1.65 * frame.normal)).norm(), 0.0,
              1e-12);
  const Eigen::Matrix3d r = world_from_cam.linear();
  EXPECT_NEAR((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  // Without pitch and roll the camera looks along the road with y down the normal.
  state.pitch = state.roll = 0.0;
  const Eigen::Matrix3d level = VehicleMotion::WorldFromCam(line, state, 1.65).linear();
  EXPECT_NEAR((level.col(2) - frame.tangent).norm(), 0.0, 1e-12);
  EXPECT_NEAR((level.col(1) + frame.normal).norm(), 0.0, 1e-12);
  // Positive pitch looks up: the optical axis gains height.
  state.pitch = 0.05;
  const Eigen::Matrix3d up = VehicleMotion::WorldFromCam(line, state, 1.65).linear();
  EXPECT_GT(up.col(2).dot(frame.normal), 0.04);
}

// A camera L ahead of the point that follows a circle of radius R moves on a circle of radius
// sqrt(R^2 + L^2), at atan(L / R) to its optical axis; at L = 0 along it.
TEST(VehicleMotion, ACameraAheadOfTheLaneTravelsOffItsAxisInATurn) {
  const double radius = 20.0, ahead = 1.5;
  const CentreLine line({{10.0, 0.0, 0.0, 0.0, 0.0}, {100.0, 1.0 / radius, 0.0, 0.0, 0.0}});
  VehicleState a, b;
  a.position = 50.0;
  b.position = 50.001;
  for (const double camera_ahead : {0.0, ahead}) {
    const Rigid3d cam_a = VehicleMotion::WorldFromCam(line, a, 1.65, camera_ahead);
    const Rigid3d cam_b = VehicleMotion::WorldFromCam(line, b, 1.65, camera_ahead);
    const Eigen::Vector3d travel = (cam_b.translation() - cam_a.translation()).normalized();
    const double off_axis = std::acos(std::clamp(travel.dot(cam_a.linear().col(2)), -1.0, 1.0));
    EXPECT_NEAR(off_axis, std::atan(camera_ahead / radius), 1e-4) << camera_ahead;
    // Still h0 above the road's tangent plane at the lane point, and travelling parallel to it.
    const RoadFrame frame = line.FrameAt(a.position);
    EXPECT_NEAR((cam_a.translation() - frame.point).dot(frame.normal), 1.65, 1e-9);
    EXPECT_NEAR(travel.dot(frame.normal), 0.0, 1e-6);
  }
}

TEST(VehicleMotion, SameSeedSameMotion) {
  VehicleOptions options;
  options.bumps_per_km = 20.0;
  const VehicleMotion a(options, 30.0, Rng(9)), b(options, 30.0, Rng(9)), c(options, 30.0, Rng(10));
  EXPECT_EQ(a.StateAt(17.3).position, b.StateAt(17.3).position);
  EXPECT_EQ(a.StateAt(17.3).pitch, b.StateAt(17.3).pitch);
  EXPECT_NE(a.StateAt(17.3).position, c.StateAt(17.3).position);
}

}  // namespace
}  // namespace roadscale::synth
