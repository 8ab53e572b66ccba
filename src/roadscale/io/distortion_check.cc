#include "roadscale/io/distortion_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/calib3d.hpp>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

constexpr const char* kNames[] = {"k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6"};
// Below this share of the undistorted image seen by the lens the frames are mostly black.
constexpr double kMinCoveredShare = 0.5;

double Coefficient(const std::vector<double>& d, size_t i) { return i < d.size() ? d[i] : 0.0; }

// What is wrong with the model, or "" when it is usable.
std::string Problem(const PinholeCamera& camera, const std::vector<double>& d) {
  // The undistorted image's farthest corner from the principal point, in normalised units.
  const double dx = std::max(camera.cx, camera.width - camera.cx) / camera.fx;
  const double dy = std::max(camera.cy, camera.height - camera.cy) / camera.fy;
  const double r_max = std::hypot(dx, dy);
  constexpr int kSteps = 4000;
  double previous = 0.0;
  for (int i = 1; i <= kSteps; ++i) {
    const double r = r_max * i / kSteps;
    const double r2 = r * r;
    const double numerator =
        1.0 + r2 * (Coefficient(d, 0) + r2 * (Coefficient(d, 1) + r2 * Coefficient(d, 4)));
    const double denominator =
        1.0 + r2 * (Coefficient(d, 5) + r2 * (Coefficient(d, 6) + r2 * Coefficient(d, 7)));
    if (!(denominator > 0.0)) {
      return "makes the rational model's denominator 1 + k4 r^2 + k5 r^4 + k6 r^6 zero inside "
             "the image";
    }
    const double distorted = r * numerator / denominator;
    if (!std::isfinite(distorted) || !(distorted > previous)) {
      char text[200];
      std::snprintf(text, sizeof(text),
                    "folds the undistortion map inside the image (the distorted radius stops "
                    "growing at %.0f %% of the way to the corner): two parts of the image would "
                    "come from one part of the lens",
                    100.0 * i / kSteps);
      return text;
    }
    previous = distorted;
  }
  // Where each undistorted pixel comes from, on a grid of about 100 x 100 samples.
  const cv::Mat K =
      (cv::Mat_<double>(3, 3) << camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0, 0, 1);
  std::vector<cv::Point2f> ideal;
  const int step = std::max(1, std::min(camera.width, camera.height) / 100);
  for (int v = 0; v < camera.height; v += step) {
    for (int u = 0; u < camera.width; u += step) ideal.emplace_back(u, v);
  }
  std::vector<cv::Point3f> rays;
  for (const cv::Point2f& p : ideal) {
    rays.emplace_back((p.x - camera.cx) / camera.fx, (p.y - camera.cy) / camera.fy, 1.0f);
  }
  std::vector<cv::Point2f> source;
  cv::projectPoints(rays, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, cv::Mat(d), source);
  const auto covered = std::count_if(source.begin(), source.end(), [&](const cv::Point2f& p) {
    return p.x >= 0.0f && p.y >= 0.0f && p.x <= camera.width - 1 && p.y <= camera.height - 1;
  });
  const double share = static_cast<double>(covered) / static_cast<double>(source.size());
  if (share < kMinCoveredShare) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "leaves %.0f %% of the undistorted image outside the lens's image (at most "
                  "%.0f %% may be): the frames would be blank",
                  100.0 * (1.0 - share), 100.0 * (1.0 - kMinCoveredShare));
    return text;
  }
  return "";
}

}  // namespace

void CheckDistortionMap(const PinholeCamera& camera, const std::vector<double>& distortion) {
  if (distortion.empty()) return;
  const std::string problem = Problem(camera, distortion);
  if (problem.empty()) return;
  for (size_t i = 0; i < distortion.size(); ++i) {
    if (distortion[i] == 0.0) continue;
    std::vector<double> without = distortion;
    without[i] = 0.0;
    if (!Problem(camera, without).empty()) continue;
    char value[40];
    std::snprintf(value, sizeof(value), "%g", distortion[i]);
    CheckOption(false, (std::string("camera.") + kNames[i]).c_str(),
                std::string(value) + " " + problem);
  }
  std::string names;
  for (size_t i = 0; i < distortion.size(); ++i)
    names += (i == 0 ? "" : "/") + std::string(kNames[i]);
  CheckOption(false, ("camera." + names).c_str(), problem);
}

}  // namespace roadscale
