// Milliseconds per frame of the shipped ESPNetv2 sizes through OnnxSegmenter (preprocessing,
// inference, argmax, resizing the label map back, masks) on a grey KITTI 00 frame.
//
//   build/bench/roadscale_segmentation_bench
//
// OpenCV's CPU backend; the thread count is the second argument (2 is the default of
// OnnxSegmenter::Options). "Time" is wall-clock time per frame; "CPU" is the CPU time of the
// whole process (all DNN threads) per frame, which other programs sharing the cores disturb
// less. Results are in docs/benchmark-history.md, "Segmentation".
#include <filesystem>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include <benchmark/benchmark.h>

#include "roadscale/segmentation/onnx_segmenter.h"
#include "roadscale/util/shared_data.h"

namespace roadscale {
namespace {

const char* const kSizes[] = {"640x192", "512x256", "1024x320", "1024x512"};

void BM_EspNetV2Segment(benchmark::State& state) {
  const std::string size = kSizes[state.range(0)];
  const std::string yaml =
      std::string(ROADSCALE_SOURCE_DIR) + "/config/models/espnetv2_" + size + ".yaml";
  const std::filesystem::path frame = SharedDataDir() / "kitti/sequences/00/image_0/000000.png";
  if (!std::filesystem::is_regular_file(frame)) {
    state.SkipWithError(("missing shared data: " + frame.string()).c_str());
    return;
  }
  OnnxSegmenter::Options options;
  options.dnn_threads = static_cast<int>(state.range(1));
  OnnxSegmenter segmenter(ReadSegmentationModel(yaml), options);
  const cv::Mat image = cv::imread(frame.string(), cv::IMREAD_UNCHANGED);
  for (auto _ : state) {
    const SegmentationResult result = segmenter.Segment(image, "000000");
    benchmark::DoNotOptimize(result.road_mask.data);
  }
  state.SetLabel(size + ", " + std::to_string(state.range(1)) + " threads");
}
BENCHMARK(BM_EspNetV2Segment)
    ->ArgsProduct({{0, 1, 2, 3}, {2}})
    ->Args({0, 1})
    ->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->MinTime(3.0);

}  // namespace
}  // namespace roadscale

BENCHMARK_MAIN();
