// Frame loading speed and memory of the io/ frame sources on the shared KITTI 00 frames.
//
//   build/bench/roadscale_frame_source_bench
//
// Memory: run BM_KittiSequentialRead/20$ and /200$ alone under /usr/bin/time -v and compare
// "Maximum resident set size"; a source that kept its frames would grow by 180 x 467 KB.
#include <filesystem>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "roadscale/io/frame_source.h"
#include "roadscale/util/shared_data.h"

namespace roadscale {
namespace {

std::string SharedSequence00() { return (SharedDataDir() / "kitti/sequences/00").string(); }

bool HaveSharedSequence00(benchmark::State& state) {
  if (std::filesystem::is_directory(SharedSequence00())) return true;
  state.SkipWithError(("missing shared data: " + SharedSequence00()).c_str());
  return false;
}

// Decoding one 1241x376 grey KITTI PNG through the source (file system cache warm after the
// first pass over the 200 frames).
void BM_KittiLoadPng(benchmark::State& state) {
  if (!HaveSharedSequence00(state)) return;
  FrameSourceOptions options;
  options.input = SharedSequence00();
  options.color = state.range(0) != 0;
  const KittiSequence source(options);
  size_t position = 0;
  for (auto _ : state) {
    Frame frame = source.Read(position);
    benchmark::DoNotOptimize(frame.image.data);
    position = (position + 1) % source.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_KittiLoadPng)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Opening the sequence (listing, calib, times, 4,541 poses) and reading the first N frames
// one after the other, as the pipeline does.
void BM_KittiSequentialRead(benchmark::State& state) {
  if (!HaveSharedSequence00(state)) return;
  FrameSourceOptions options;
  options.input = SharedSequence00();
  options.frames.end = static_cast<size_t>(state.range(0));
  for (auto _ : state) {
    std::unique_ptr<FrameSource> source = OpenFrameSource(options);
    Frame frame;
    while (source->Next(&frame)) benchmark::DoNotOptimize(frame.image.data);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_KittiSequentialRead)->Arg(20)->Arg(200)->Unit(benchmark::kMillisecond);

// Opening alone: what a run pays before its first frame.
void BM_KittiOpen(benchmark::State& state) {
  if (!HaveSharedSequence00(state)) return;
  FrameSourceOptions options;
  options.input = SharedSequence00();
  for (auto _ : state) {
    KittiSequence source(options);
    benchmark::DoNotOptimize(source.size());
  }
}
BENCHMARK(BM_KittiOpen)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace roadscale

BENCHMARK_MAIN();
