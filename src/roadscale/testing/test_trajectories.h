#pragma once

// Trajectories for the eval tests (header-only; not part of the library).

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "roadscale/geometry/rigid3.h"

#include <Eigen/Geometry>

namespace roadscale::testing {

inline Rigid3d YawPitchStep(double yaw, double pitch, const Eigen::Vector3d& translation) {
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  return MakeRigid3d(rotation, translation);
}

// `frames` poses one metre apart straight along the camera's z axis.
inline std::vector<Rigid3d> StraightMetreSteps(int frames) {
  std::vector<Rigid3d> poses;
  for (int i = 0; i < frames; ++i) {
    poses.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i)));
  }
  return poses;
}

// A car-like drive in the KITTI camera frame (y down, z forward): `frames` poses about
// `step_m` apart, turning left and right and rising and falling a little.
inline std::vector<Rigid3d> CurvyDrive(int frames, double step_m) {
  std::vector<Rigid3d> poses = {Rigid3d::Identity()};
  for (int i = 1; i < frames; ++i) {
    const double yaw = 0.02 * std::sin(i / 45.0) + 0.004;
    const double pitch = 0.002 * std::sin(i / 23.0);
    const double speed = step_m * (1.0 + 0.3 * std::sin(i / 80.0));
    poses.push_back(poses.back() * YawPitchStep(yaw, pitch, Eigen::Vector3d(0.0, 0.0, speed)));
  }
  return poses;
}

// Uniform in [-1, 1) from mt19937's raw output, whose sequence the C++ standard fixes (the
// standard's distributions are implementation-defined, so they are not used).
class PortableUniform {
 public:
  explicit PortableUniform(uint32_t seed) : engine_(seed) {}
  double operator()() { return 2.0 * (static_cast<double>(engine_()) / 4294967296.0) - 1.0; }

 private:
  std::mt19937 engine_;
};

// An "estimate" of `gt`: the ground truth's frame-to-frame motions with their translation
// scaled by a slowly drifting factor (1 + scale_drift * i / n) and by (1 + step_noise u),
// and their rotation perturbed by up to rotation_noise_rad about each axis (u uniform,
// seeded). Starts at gt[0].
inline std::vector<Rigid3d> PerturbedEstimate(const std::vector<Rigid3d>& gt, uint32_t seed,
                                              double scale_drift, double step_noise,
                                              double rotation_noise_rad) {
  PortableUniform uniform(seed);
  std::vector<Rigid3d> est = {gt.front()};
  const double n = static_cast<double>(gt.size());
  for (size_t i = 0; i + 1 < gt.size(); ++i) {
    const Rigid3d step = gt[i].inverse() * gt[i + 1];
    const double scale =
        (1.0 + scale_drift * static_cast<double>(i) / n) * (1.0 + step_noise * uniform());
    // One draw a statement: the order of an expression's operands is the compiler's, and the
    // devkit's numbers in kitti_odometry_metric_test.cc were computed in this order.
    const double about_z = rotation_noise_rad * uniform();
    const double about_y = rotation_noise_rad * uniform();
    const double about_x = rotation_noise_rad * uniform();
    const Eigen::Matrix3d noise = (Eigen::AngleAxisd(about_x, Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(about_y, Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(about_z, Eigen::Vector3d::UnitZ()))
                                      .toRotationMatrix();
    // KITTI's rotation blocks are orthonormal only to their 7 printed digits; chaining 2,000
    // such products would let the estimate's rotations drift away from orthonormal.
    est.push_back(est.back() *
                  MakeRigid3d(noise * NearestRotation(step.linear()), scale * step.translation()));
  }
  return est;
}

}  // namespace roadscale::testing
