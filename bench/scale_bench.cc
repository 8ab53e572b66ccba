// Cost of the scale stage per frame pair (triangulation, Alg. 1, Alg. 2, RANSAC, filter) on
// synthetic street pairs with a growing number of tracks:
//
//   build/bench/roadscale_scale_bench
//
// Real KITTI tracks: the "ms" column of roadscale_scale_on_kitti.
#include <benchmark/benchmark.h>

#include "roadscale/scale/scale_estimator.h"
#include "roadscale/testing/synthetic_road_scene.h"

namespace roadscale {
namespace {

void BM_ScaleEstimate(benchmark::State& state) {
  const Plane road{Eigen::Vector3d::UnitY(), 1.65};
  testing::SceneOptions scene;
  scene.num_road = static_cast<int>(state.range(0));
  scene.num_wall = scene.num_road / 3;
  scene.num_car = scene.num_road / 5;
  scene.num_above_horizon = scene.num_road / 3;
  const Rigid3d motion = testing::DriveAlongRoad(road, 1.0, 0.01);
  const PinholeCamera camera = KittiOdometryCamera();
  const testing::TwoViewObservations pair =
      testing::ObserveTwoViews(testing::MakeStreetScene(scene), motion, camera, 0.3, 7);
  const cv::Mat mask = testing::MaskFromLabels(
      pair, camera, {testing::SceneLabel::kRoad, testing::SceneLabel::kCar}, 4);
  ScaleEstimator estimator(camera, ScaleEstimatorOptions());
  for (auto _ : state) {
    benchmark::DoNotOptimize(estimator.Estimate(pair.prev_pixels, pair.cur_pixels, motion, mask));
  }
  state.counters["tracks"] = static_cast<double>(pair.prev_pixels.size());
}
BENCHMARK(BM_ScaleEstimate)
    ->Arg(250)
    ->Arg(500)
    ->Arg(1000)
    ->Arg(2000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace roadscale

BENCHMARK_MAIN();
