// Cost of each frontend stage on the shared KITTI 00 frames (1241x376 grey): detection per
// detector, KLT tracking (pyramid + forward and backward passes), two-view motion.
//
//   build/bench/roadscale_frontend_bench --benchmark_min_time=2
//
// Each benchmark cycles over pairs of consecutive frames 0..199 so that no single image
// decides the result; images are decoded before timing starts.
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include <benchmark/benchmark.h>

#include "roadscale/frontend/feature_detector.h"
#include "roadscale/frontend/klt_tracker.h"
#include "roadscale/frontend/two_view_motion.h"
#include "roadscale/io/kitti_calib.h"
#include "roadscale/util/shared_data.h"

namespace roadscale {
namespace {

constexpr int kFrames = 200;
constexpr int kStride = 10;  // frames 0, 10, 20, ... start the pairs

std::string FramePath(int index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06d.png", index);
  return (SharedDataDir() / "kitti/sequences/00/image_0" / name).string();
}

// The frames at 0, 10, ..., 190 and the frame after each, or empty when the data is missing.
const std::vector<std::pair<cv::Mat, cv::Mat>>& FramePairs() {
  static const std::vector<std::pair<cv::Mat, cv::Mat>> pairs = [] {
    std::vector<std::pair<cv::Mat, cv::Mat>> result;
    for (int i = 0; i + 1 < kFrames; i += kStride) {
      cv::Mat a = cv::imread(FramePath(i), cv::IMREAD_GRAYSCALE);
      cv::Mat b = cv::imread(FramePath(i + 1), cv::IMREAD_GRAYSCALE);
      if (a.empty() || b.empty()) return std::vector<std::pair<cv::Mat, cv::Mat>>();
      result.emplace_back(a, b);
    }
    return result;
  }();
  return pairs;
}

bool HaveFrames(benchmark::State& state) {
  if (!FramePairs().empty()) return true;
  state.SkipWithError(("missing shared data: " + FramePath(0)).c_str());
  return false;
}

// Detection on an empty grid (the first frame, or a re-detection after losing every track):
// the most a frame can cost.
void BM_Detect(benchmark::State& state) {
  if (!HaveFrames(state)) return;
  FeatureDetectorOptions options;
  options.type = static_cast<DetectorType>(state.range(0));
  options.sift_half_resolution = state.range(1) != 0;
  const FeatureDetector detector(options);
  size_t i = 0;
  size_t features = 0;
  for (auto _ : state) {
    features += detector.Detect(FramePairs()[i].first, cv::Mat()).size();
    i = (i + 1) % FramePairs().size();
  }
  state.SetLabel(DetectorTypeName(options.type) +
                 (options.type == DetectorType::kSift
                      ? (options.sift_half_resolution ? " (half resolution)" : " (full resolution)")
                      : ""));
  state.counters["features"] =
      benchmark::Counter(static_cast<double>(features), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_Detect)
    ->Args({static_cast<int>(DetectorType::kSift), 1})
    ->Args({static_cast<int>(DetectorType::kSift), 0})
    ->Args({static_cast<int>(DetectorType::kOrb), 0})
    ->Args({static_cast<int>(DetectorType::kBrisk), 0})
    ->Args({static_cast<int>(DetectorType::kAkaze), 0})
    ->Args({static_cast<int>(DetectorType::kFast), 0})
    ->Unit(benchmark::kMillisecond);

// What the tracker does every frame: the new frame's pyramid, then KLT of the previous
// frame's features into it and back (the previous pyramid is kept from the last frame). The
// arguments are the window size and the backward pass's coarsest pyramid level.
void BM_KltTrack(benchmark::State& state) {
  if (!HaveFrames(state)) return;
  KltOptions options;
  options.window_size = static_cast<int>(state.range(0));
  options.backward_pyramid_levels = static_cast<int>(state.range(1));
  const FeatureDetector detector({});
  std::vector<KltPyramid> previous;
  std::vector<std::vector<cv::Point2f>> points;
  for (const auto& [a, b] : FramePairs()) {
    previous.push_back(BuildKltPyramid(a, options));
    points.push_back(detector.Detect(a, cv::Mat()));
  }
  size_t i = 0;
  size_t tracked = 0;
  size_t total = 0;
  for (auto _ : state) {
    const KltPyramid current = BuildKltPyramid(FramePairs()[i].second, options);
    const KltResult result = TrackKlt(previous[i], current, points[i], {}, options);
    for (bool ok : result.ok) tracked += ok;
    total += points[i].size();
    i = (i + 1) % FramePairs().size();
  }
  state.SetLabel(std::to_string(options.window_size) + " px window, backward pass to level " +
                 std::to_string(options.backward_pyramid_levels));
  state.counters["points"] =
      benchmark::Counter(static_cast<double>(total), benchmark::Counter::kAvgIterations);
  state.counters["tracked"] =
      benchmark::Counter(static_cast<double>(tracked), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_KltTrack)->Args({21, 3})->Args({21, 1})->Args({21, 0})->Unit(benchmark::kMillisecond);

// The two-view motion (stationary / rotation checks, 5-point RANSAC, recoverPose and the
// Sampson refinement) on the tracked correspondences of each pair.
void BM_TwoViewMotion(benchmark::State& state) {
  if (!HaveFrames(state)) return;
  const PinholeCamera camera =
      ReadKittiCamera((SharedDataDir() / "kitti/sequences/00/calib.txt").string(), 0, 1241, 376);
  const KltOptions klt;
  const FeatureDetector detector({});
  std::vector<std::vector<Correspondence>> pairs;
  for (const auto& [a, b] : FramePairs()) {
    const std::vector<cv::Point2f> points = detector.Detect(a, cv::Mat());
    const KltResult result =
        TrackKlt(BuildKltPyramid(a, klt), BuildKltPyramid(b, klt), points, {}, klt);
    std::vector<Correspondence> correspondences;
    for (size_t k = 0; k < points.size(); ++k) {
      if (!result.ok[k]) continue;
      correspondences.push_back({static_cast<int64_t>(k),
                                 {points[k].x, points[k].y},
                                 {result.points[k].x, result.points[k].y}});
    }
    pairs.push_back(std::move(correspondences));
  }
  TwoViewMotionOptions options;
  options.refine = state.range(0) != 0;
  size_t i = 0;
  size_t correspondences = 0;
  for (auto _ : state) {
    const TwoViewMotion motion = EstimateTwoViewMotion(pairs[i], camera, options);
    benchmark::DoNotOptimize(motion.rotation.data());
    correspondences += pairs[i].size();
    i = (i + 1) % pairs.size();
  }
  state.SetLabel(options.refine ? "with refinement" : "without refinement");
  state.counters["correspondences"] =
      benchmark::Counter(static_cast<double>(correspondences), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_TwoViewMotion)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace roadscale

BENCHMARK_MAIN();
