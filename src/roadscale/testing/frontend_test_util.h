#pragma once

#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "roadscale/frontend/two_view_motion.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/util/random.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace roadscale::testing {

// A grey image of random, non-periodic texture defined at every real position, so that a
// shifted copy is exact to any sub-pixel shift: a sum of Gaussian blobs of random sign at
// random places, with radii from 1.5 to 16 px (log-uniform) so that the coarse levels of an
// image pyramid keep texture too. Pixel (x, y) of the result shows the texture at
// (x - shift_x, y - shift_y): the texture moves by +shift.
inline cv::Mat SyntheticTexture(int width, int height, double shift_x = 0.0, double shift_y = 0.0,
                                unsigned seed = 7) {
  Rng rng(seed);
  const int margin = 200;  // blobs also outside the image, so that shifted content exists
  const int blobs = (width + 2 * margin) * (height + 2 * margin) / 60;
  cv::Mat accumulator(height, width, CV_64FC1, cv::Scalar(128.0));
  for (int b = 0; b < blobs; ++b) {
    const double bx = rng.Uniform(-margin, width + margin) + shift_x;
    const double by = rng.Uniform(-margin, height + margin) + shift_y;
    const double r = std::exp(rng.Uniform(std::log(1.5), std::log(16.0)));
    const double a = rng.Uniform(-60.0, 60.0);
    const int reach = static_cast<int>(std::ceil(3.5 * r));
    const int x0 = std::max(0, static_cast<int>(std::floor(bx)) - reach);
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil(bx)) + reach);
    const int y0 = std::max(0, static_cast<int>(std::floor(by)) - reach);
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil(by)) + reach);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double dx = x - bx;
        const double dy = y - by;
        accumulator.at<double>(y, x) += a * std::exp(-(dx * dx + dy * dy) / (2.0 * r * r));
      }
    }
  }
  cv::Mat image;
  accumulator.convertTo(image, CV_8UC1);
  return image;
}

// A rotation from yaw, pitch and roll in degrees (about the camera's y, x and z axes).
inline Eigen::Matrix3d RotationFromDegrees(double yaw, double pitch, double roll) {
  const double d = M_PI / 180.0;
  return (Eigen::AngleAxisd(yaw * d, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(pitch * d, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(roll * d, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

struct TwoViewScene {
  std::vector<Correspondence> correspondences;
  std::vector<bool> is_outlier;
};

// Random points of a street-like scene (x in [-20, 20] m, y in [-6, 2] m, z in [z_min, z_max]
// m in the previous camera) seen from two cameras related by cur_from_prev = (R, t), projected
// with Gaussian pixel noise. Only points visible in both images are kept. A share of
// `outlier_ratio` of them get a current position displaced by 5-60 px in a random direction.
inline TwoViewScene MakeTwoViewScene(const PinholeCamera& camera, const Eigen::Matrix3d& R,
                                     const Eigen::Vector3d& t, int count, double noise_px,
                                     double outlier_ratio = 0.0, unsigned seed = 3,
                                     double z_min = 4.0, double z_max = 60.0) {
  Rng rng(seed);
  TwoViewScene scene;
  while (static_cast<int>(scene.correspondences.size()) < count) {
    // One draw a statement: the order of a call's arguments is the compiler's, and the scene
    // must be the same with every compiler.
    const double z = rng.Uniform(z_min, z_max);
    const double y = rng.Uniform(-6.0, 2.0);
    const double x = rng.Uniform(-20.0, 20.0);
    const Eigen::Vector3d X(x, y, z);
    const Eigen::Vector3d Y = R * X + t;
    if (Y.z() < 1.0) continue;
    Correspondence c;
    c.track_id = static_cast<int64_t>(scene.correspondences.size()) * 3 + 1;
    const double prev_dy = noise_px * rng.Normal();
    const double prev_dx = noise_px * rng.Normal();
    const double cur_dy = noise_px * rng.Normal();
    const double cur_dx = noise_px * rng.Normal();
    c.prev = camera.Project(X) + Eigen::Vector2d(prev_dx, prev_dy);
    c.cur = camera.Project(Y) + Eigen::Vector2d(cur_dx, cur_dy);
    if (!camera.IsInside(c.prev) || !camera.IsInside(c.cur)) continue;
    const bool outlier = rng.Bernoulli(outlier_ratio);
    if (outlier) {
      const double a = rng.Uniform(0.0, 2.0 * M_PI);
      const double r = rng.Uniform(5.0, 60.0);
      c.cur += r * Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    scene.correspondences.push_back(c);
    scene.is_outlier.push_back(outlier);
  }
  return scene;
}

}  // namespace roadscale::testing
