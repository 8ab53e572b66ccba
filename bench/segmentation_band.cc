// Whether the network's pixels are better spent on the image below the horizon: each shipped
// ESPNetv2 input size run on the whole frame and on the band from `margin` rows above the
// horizon to the bottom (the rows above labelled as neither road nor moving object).
//
//   build/bench/roadscale_segmentation_band [--frames 200] [--margins 40,80,120]
//
// The networks take one fixed input size (OpenCV cannot reshape their graphs), so a band
// costs what the whole frame costs at the same size: the band only helps if a smaller size
// on the band does as well as a larger one on the whole frame.
// 1. Road and dynamic-class IoU on the 5 labelled KITTI images (grey, as roadscale runs),
//    counted as the Cityscapes benchmark does.
// 2. On the grey KITTI 00 frames: agreement of each variant's masks (dynamic mask dilated as
//    the pipeline uses it) with the default's (512x256 on the whole frame), the share of the
//    default's dynamic pixels the variant misses, and the inference's CPU ms (1 thread).
// The horizon row is KITTI 00's principal point row (its camera looks level).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <opencv2/core/utility.hpp>

#include "roadscale/io/kitti_calib.h"
#include "roadscale/pipeline/thread_cpu_time.h"
#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/segmentation/label_iou.h"
#include "roadscale/segmentation/onnx_segmenter.h"
#include "roadscale/util/error.h"
#include "roadscale/util/shared_data.h"

#include "segmentation_bench_data.h"

namespace roadscale {
namespace {

constexpr int kNeitherClass = 255;

// A way to segment a frame: a network size and the first image row it sees (0: all).
struct Variant {
  std::string size;
  int margin_px = -1;  // rows above the horizon; -1: the whole frame
  int first_row = 0;

  std::string Name() const {
    return size + (margin_px < 0 ? " whole frame" : " band, margin " + std::to_string(margin_px));
  }
};

// Labels of the whole image: the network's on rows first_row.., kNeitherClass above.
cv::Mat BandLabels(OnnxSegmenter& network, const cv::Mat& image, int first_row) {
  if (first_row <= 0) return network.Labels(image);
  cv::Mat labels(image.size(), CV_8UC1, cv::Scalar(kNeitherClass));
  network.Labels(image.rowRange(first_row, image.rows))
      .copyTo(labels.rowRange(first_row, image.rows));
  return labels;
}

void Run(const std::vector<Variant>& variants, int frames) {
  const std::vector<LabelledImage> labelled = ReadLabelledKittiImages();
  std::vector<cv::Mat> frames_00;
  for (int t = 0; t < frames; ++t) frames_00.push_back(ReadKitti00Frame(t));
  const MaskClasses classes;
  const MaskOptions mask_options;
  OnnxSegmenter::Options network_options;
  network_options.dnn_threads = 1;

  OnnxSegmenter reference_network(ReadSegmentationModel(ShippedModelYaml("512x256")),
                                  network_options);
  std::vector<SegmentationResult> reference;
  for (const cv::Mat& image : frames_00) {
    reference.push_back(DeriveMasks(reference_network.Labels(image), classes, mask_options));
  }

  std::printf(
      "variant                       | first row | labelled: road IoU | dynamic IoU | KITTI 00 "
      "against 512x256 whole: road IoU | dynamic IoU | dynamic px missed | CPU ms\n");
  for (const Variant& variant : variants) {
    OnnxSegmenter network(ReadSegmentationModel(ShippedModelYaml(variant.size)), network_options);
    ClassSetIou labelled_road, labelled_dynamic;
    for (const LabelledImage& image : labelled) {
      const cv::Mat predicted = BandLabels(network, image.grey, variant.first_row);
      labelled_road.Add(predicted, image.truth, {kRoadTrainId});
      labelled_dynamic.Add(predicted, image.truth, CityscapesDynamicTrainIds());
    }

    PooledMaskIou road, dynamic;
    double missed = 0.0, dynamic_pixels = 0.0, cpu_ms = 0.0;
    for (int t = 0; t < frames; ++t) {
      const double cpu_start = ThreadCpuMs();
      const cv::Mat labels = BandLabels(network, frames_00[t], variant.first_row);
      cpu_ms += ThreadCpuMs() - cpu_start;
      const SegmentationResult masks = DeriveMasks(labels, classes, mask_options);
      road.Add(masks.road_mask, reference[t].road_mask);
      dynamic.Add(masks.dynamic_mask, reference[t].dynamic_mask);
      const cv::Mat raw_reference = LabelsInSet(reference[t].labels, classes.dynamic_ids);
      missed += cv::countNonZero(raw_reference & ~masks.dynamic_mask);
      dynamic_pixels += cv::countNonZero(raw_reference);
    }
    std::printf("%-29s | %9d | %18.3f | %11.3f | %36.3f | %11.3f | %15.1f %% | %6.0f\n",
                variant.Name().c_str(), variant.first_row, labelled_road.Iou(),
                labelled_dynamic.Iou(), road.Iou(), dynamic.Iou(), 100.0 * missed / dynamic_pixels,
                cpu_ms / frames);
    std::fflush(stdout);
  }
}

std::vector<int> ParseMargins(const std::string& text) {
  std::vector<int> margins;
  size_t start = 0;
  while (start < text.size()) {
    const size_t comma = text.find(',', start);
    const size_t end = comma == std::string::npos ? text.size() : comma;
    margins.push_back(std::atoi(text.substr(start, end - start).c_str()));
    start = end + 1;
  }
  return margins;
}

}  // namespace
}  // namespace roadscale

int main(int argc, char** argv) {
  int frames = 200;
  std::vector<int> margins = {40, 80, 120};
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--frames" && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else if (argument == "--margins" && i + 1 < argc) {
      margins = roadscale::ParseMargins(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--frames 200] [--margins 40,80,120]\n", argv[0]);
      return 2;
    }
  }
  if (frames < 1 || frames > 4541) {
    std::fprintf(stderr, "error: --frames must be in 1..4541 (KITTI 00's frames)\n");
    return 2;
  }
  for (const int margin : margins) {
    if (margin < 0) {
      std::fprintf(stderr, "error: --margins must be rows (0 or more), comma-separated\n");
      return 2;
    }
  }
  try {
    const roadscale::PinholeCamera camera = roadscale::ReadKittiCamera(
        (roadscale::SharedDataDir() / "kitti/sequences/00/calib.txt").string(), 0, 1241, 376);
    const int horizon_row = static_cast<int>(std::lround(camera.cy));
    std::vector<roadscale::Variant> variants;
    for (const std::string size : {"512x256", "640x192"}) {
      variants.push_back({size, -1, 0});
      for (const int margin : margins) {
        variants.push_back({size, margin, std::max(0, horizon_row - margin)});
      }
    }
    roadscale::Run(variants, frames);
  } catch (const roadscale::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
