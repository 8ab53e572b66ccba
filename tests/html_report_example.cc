// Writes an example run report (roadscale/eval/html_report.h) from made-up data, for the
// check that reports render in a browser (report_render_test.sh) and for the README's
// screenshot (docs/images/report_example.png). The numbers imitate a run (a drive with a stop,
// noisy raw scale, a filtered one, stages losing points, held frames) but come from no pipeline.
//
//   roadscale_html_report_example OUT.html [--no-ground-truth] [--frames N (600)]

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "roadscale/eval/html_report.h"
#include "roadscale/eval/trajectory_evaluation.h"
#include "roadscale/util/error.h"

#include <Eigen/Geometry>

namespace roadscale {
namespace {

// Uniform in [-1, 1) from mt19937's raw output (fixed by the standard, unlike distributions).
class Uniform {
 public:
  explicit Uniform(uint32_t seed) : engine_(seed) {}
  double operator()() { return 2.0 * (static_cast<double>(engine_()) / 4294967296.0) - 1.0; }

 private:
  std::mt19937 engine_;
};

HtmlReportInput ExampleRun(bool with_ground_truth, int frames) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Uniform uniform(7);
  HtmlReportInput input;
  input.title = "roadscale run: example drive (made-up data)";
  input.inputs = {{"images", "example/images (10 Hz)"},
                  {"camera", "example/camera.yaml"},
                  {"config", "config/kitti.yaml"},
                  {"segmentation", "models/espnetv2_512x256.onnx"},
                  {"camera height h0", "1.65 m"}};

  FrameSeries raw{"scale_raw", FrameSeriesKind::kScale, {}};
  FrameSeries filtered{"scale_filtered", FrameSeriesKind::kScale, {}};
  FrameSeries truth{"scale_true", FrameSeriesKind::kScale, {}};
  FrameSeries road{"points_road_mask", FrameSeriesKind::kCount, {}};
  FrameSeries vote{"points_vote", FrameSeriesKind::kCount, {}};
  FrameSeries model{"points_model_check", FrameSeriesKind::kCount, {}};
  FrameSeries inliers{"ransac_inliers", FrameSeriesKind::kCount, {}};
  FrameSeries ms_segmentation{"ms_segmentation", FrameSeriesKind::kMilliseconds, {}};
  FrameSeries ms_frontend{"ms_frontend", FrameSeriesKind::kMilliseconds, {}};
  FrameSeries ms_scale{"ms_scale", FrameSeriesKind::kMilliseconds, {}};
  FrameSeries plane_h{"plane_h", FrameSeriesKind::kOther, {}};

  Rigid3d gt = Rigid3d::Identity();
  Rigid3d est = Rigid3d::Identity();
  double last_scale = 1.0;
  for (int i = 0; i < frames; ++i) {
    // Metres per frame: cruising, braking to a stop at frames 300-329, pulling away.
    const double speed = i >= 300 && i < 330   ? 0.0
                         : i >= 270 && i < 300 ? 1.2 * (300 - i) / 30.0
                         : i >= 330 && i < 360 ? 1.2 * (i - 330) / 30.0
                                               : 1.2 + 0.2 * std::sin(i / 50.0);
    const double yaw = speed > 0.0 ? 0.012 * std::sin(i / 70.0) + 0.003 : 0.0;
    const bool stationary = speed == 0.0;
    // Frames 420-440 see too little road: the scale is held.
    const bool held = i >= 420 && i < 441;
    const double road_points = held ? 30 + 10 * uniform() : 320 + 60 * uniform();
    const double vote_points = road_points * (0.62 + 0.05 * uniform());
    const double model_points = held ? 8 + 3 * uniform() : vote_points * (0.7 + 0.05 * uniform());
    const double scale_raw = stationary || held ? kNaN : speed * (1.0 + 0.04 * uniform());
    if (std::isfinite(scale_raw)) last_scale += std::clamp(scale_raw - last_scale, -0.3, 0.3) * 0.6;
    const double scale_used = stationary ? 0.0 : last_scale;

    input.frame_status.push_back(stationary ? "stationary" : held ? "held" : "ok");
    raw.values.push_back(scale_raw);
    filtered.values.push_back(stationary ? kNaN : last_scale);
    truth.values.push_back(stationary ? kNaN : speed);
    road.values.push_back(std::round(road_points));
    vote.values.push_back(std::round(vote_points));
    model.values.push_back(std::round(model_points));
    inliers.values.push_back(held ? kNaN : std::round(model_points * 0.9));
    plane_h.values.push_back(std::isfinite(scale_raw) ? 1.65 / scale_raw : kNaN);
    ms_segmentation.values.push_back(41.0 + 4.0 * uniform() + (i % 97 == 0 ? 20.0 : 0.0));
    ms_frontend.values.push_back(24.0 + 5.0 * uniform());
    ms_scale.values.push_back(stationary ? 0.2 : 5.5 + 2.0 * uniform());

    if (i > 0) {
      const Eigen::Matrix3d rotation =
          Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
      gt = gt * MakeRigid3d(rotation, Eigen::Vector3d(0.0, 0.0, speed));
      // A small yaw bias, as a frontend's rotation drifts.
      const double yaw_error = 1e-4 + 2e-4 * uniform();
      est = est * MakeRigid3d(
                      rotation *
                          Eigen::AngleAxisd(yaw_error, Eigen::Vector3d::UnitY()).toRotationMatrix(),
                      Eigen::Vector3d(0.0, 0.0, scale_used));
    }
    input.gt_world_from_cam.push_back(gt);
    input.est_world_from_cam.push_back(est);
  }
  input.series = {raw,     filtered, truth,           road,        vote,    model,
                  inliers, plane_h,  ms_segmentation, ms_frontend, ms_scale};
  input.wall_time_s = 0.044 * frames;
  if (frames > 420) input.warnings = {"frames 420-440: too few road points, the scale was held"};
  // The metrics need two poses.
  if (with_ground_truth && frames >= 2) {
    input.evaluation = EvaluateTrajectory(input.gt_world_from_cam, input.est_world_from_cam);
  } else if (!with_ground_truth) {
    input.gt_world_from_cam.clear();
    input.series.erase(input.series.begin() + 2);  // scale_true needs ground truth
  }
  return input;
}

}  // namespace
}  // namespace roadscale

int main(int argc, char** argv) {
  const char* out = nullptr;
  bool with_ground_truth = true;
  int frames = 600;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-ground-truth") == 0) {
      with_ground_truth = false;
    } else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else if (out == nullptr && argv[i][0] != '-') {
      out = argv[i];
    } else {
      out = nullptr;
      break;
    }
  }
  if (out == nullptr || frames < 1) {
    std::fprintf(stderr, "usage: %s OUT.html [--no-ground-truth] [--frames N (600, >= 1)]\n",
                 argv[0]);
    return 2;
  }
  try {
    roadscale::WriteHtmlReport(out, roadscale::ExampleRun(with_ground_truth, frames));
  } catch (const roadscale::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  std::printf("%s\n", out);
  return 0;
}
