// Speed of the synthetic scene renderer (`roadscale synth`): frames per second at KITTI's
// 1241x376, with 1 and 2 rendering threads, the cost of encoding a frame's PNGs and of
// building a scene.
#include <memory>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include <benchmark/benchmark.h>

#include "roadscale/synth/synthetic_scene.h"

namespace {

using roadscale::synth::PresetNames;
using roadscale::synth::PresetSceneOptions;
using roadscale::synth::SceneOptions;
using roadscale::synth::SyntheticScene;
using roadscale::synth::SynthFrame;

constexpr int kFrames = 100;

// Renders the frames of a 100-frame sequence in turn. Arguments: preset index, threads,
// colour (0/1).
void BM_SynthRenderFrame(benchmark::State& state) {
  SceneOptions options = PresetSceneOptions(PresetNames()[state.range(0)]);
  options.image.threads = static_cast<int>(state.range(1));
  const bool colour = state.range(2) != 0;
  SyntheticScene scene(options, kFrames);
  int index = 0;
  for (auto _ : state) {
    SynthFrame frame = scene.Render(index, colour);
    benchmark::DoNotOptimize(frame.images.grey.data);
    index = (index + 1) % kFrames;
  }
  state.SetLabel(options.preset);
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SynthRenderFrame)
    ->ArgNames({"preset", "threads", "colour"})
    ->Args({0, 2, 0})
    ->Args({0, 1, 0})
    ->Args({0, 2, 1})
    ->Args({1, 2, 0})
    ->Args({2, 2, 0})
    ->Args({3, 2, 0})
    ->Args({4, 2, 0})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// Encoding one frame's PNGs as `roadscale synth` writes them (grey, labels, depth, moving).
void BM_SynthEncodeFramePngs(benchmark::State& state) {
  SceneOptions options = PresetSceneOptions("urban");
  SyntheticScene scene(options, 1);
  const SynthFrame frame = scene.Render(0, false);
  std::vector<uchar> buffer;
  for (auto _ : state) {
    for (const cv::Mat* image :
         {&frame.images.grey, &frame.images.labels, &frame.images.depth, &frame.images.moving}) {
      cv::imencode(".png", *image, buffer);
      benchmark::DoNotOptimize(buffer.data());
    }
  }
}
BENCHMARK(BM_SynthEncodeFramePngs)->Unit(benchmark::kMillisecond)->UseRealTime();

// Building a scene (road, roadside, traffic) before the first frame. Arguments: preset
// index, frames.
void BM_SynthBuildScene(benchmark::State& state) {
  const SceneOptions options = PresetSceneOptions(PresetNames()[state.range(0)]);
  for (auto _ : state) {
    auto scene = std::make_unique<SyntheticScene>(options, static_cast<int>(state.range(1)));
    benchmark::DoNotOptimize(scene.get());
  }
  state.SetLabel(options.preset);
}
BENCHMARK(BM_SynthBuildScene)
    ->ArgNames({"preset", "frames"})
    ->Args({0, 100})
    ->Args({0, 1000})
    ->Args({1, 1000})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
