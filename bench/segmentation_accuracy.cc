// Accuracy of the shipped ESPNetv2 sizes, and what segmenting only every k-th frame costs.
//
//   build/bench/roadscale_segmentation_accuracy [--reuse-sizes 640x192,1024x320] [--frames 200]
//
// 1. Road and dynamic-class IoU on the 5 labelled KITTI images of
//    shared/kitti_semantics/training (ground truth in Cityscapes label ids, resized to the
//    image with nearest neighbour), on the colour images and on their grey versions. IoU is
//    counted as the Cityscapes benchmark does (pixels the ground truth leaves unlabelled are
//    not counted); "all px" counts every pixel, unlabelled ones as neither class.
// 2. Reusing masks on the grey KITTI 00 frames: IoU of frame t's masks (as the pipeline uses
//    them: dynamic mask dilated by the default margin) against frame t+d's fresh masks, pooled
//    over the frames, and the share of frame t+d's dynamic pixels the reused mask misses.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/segmentation/label_iou.h"
#include "roadscale/segmentation/onnx_segmenter.h"
#include "roadscale/util/error.h"

#include "segmentation_bench_data.h"

namespace roadscale {
namespace {

const std::vector<std::string> kSizes = {"640x192", "512x256", "1024x320", "1024x512"};

std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const size_t end = comma == std::string::npos ? text.size() : comma;
    if (end > start) parts.push_back(text.substr(start, end - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

void LabelledImageIou() {
  const std::vector<LabelledImage> images = ReadLabelledKittiImages();
  std::printf("KITTI semantics, 5 images (IoU; 'all px' counts unlabelled pixels too)\n");
  std::printf("%-9s | %-23s | %-23s | %-23s | %-23s\n", "size", "road colour (all px)",
              "road grey (all px)", "dynamic colour (all px)", "dynamic grey (all px)");
  for (const std::string& size : kSizes) {
    OnnxSegmenter network(ReadSegmentationModel(ShippedModelYaml(size)), OnnxSegmenter::Options());
    // [colour, grey] x [road, dynamic] x [ignore excluded, all pixels]
    ClassSetIou iou[2][2][2];
    for (const LabelledImage& image : images) {
      const cv::Mat predicted[2] = {network.Labels(image.colour), network.Labels(image.grey)};
      const std::vector<int> classes[2] = {{kRoadTrainId}, CityscapesDynamicTrainIds()};
      for (int input = 0; input < 2; ++input) {
        for (int c = 0; c < 2; ++c) {
          iou[input][c][0].Add(predicted[input], image.truth, classes[c]);
          iou[input][c][1].Add(predicted[input], image.truth, classes[c], /*ignore_id=*/-1);
        }
      }
    }
    std::printf("%-9s", size.c_str());
    for (int c = 0; c < 2; ++c) {
      for (int input = 0; input < 2; ++input) {
        std::printf(" | %.3f (%.3f)          ", iou[input][c][0].Iou(), iou[input][c][1].Iou());
      }
    }
    std::printf("\n");
    std::fflush(stdout);
  }
}

void ReuseCost(const std::string& size, int frames) {
  OnnxSegmenter network(ReadSegmentationModel(ShippedModelYaml(size)), OnnxSegmenter::Options());
  std::vector<SegmentationResult> fresh;
  double milliseconds = 0.0;
  for (int t = 0; t < frames; ++t) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d", t);
    fresh.push_back(network.Segment(ReadKitti00Frame(t), name));
    milliseconds += fresh.back().milliseconds;
  }
  std::printf("%s on KITTI 00 frames 0..%d (%.0f ms a frame in this run)\n", size.c_str(),
              frames - 1, milliseconds / frames);
  std::printf("  reused after | road IoU | dynamic IoU | dynamic px missed\n");
  for (const int d : {1, 2, 3, 4}) {
    PooledMaskIou road, dynamic;
    double missed = 0.0, dynamic_pixels = 0.0;
    for (int t = 0; t + d < frames; ++t) {
      const SegmentationResult& old_masks = fresh[t];
      const SegmentationResult& now = fresh[t + d];
      road.Add(old_masks.road_mask, now.road_mask);
      dynamic.Add(old_masks.dynamic_mask, now.dynamic_mask);
      const cv::Mat raw_now = LabelsInSet(now.labels, CityscapesDynamicTrainIds());
      missed += cv::countNonZero(raw_now & ~old_masks.dynamic_mask);
      dynamic_pixels += cv::countNonZero(raw_now);
    }
    std::printf("  %d frame%s     | %.3f    | %.3f       | %.1f %%\n", d, d == 1 ? " " : "s",
                road.Iou(), dynamic.Iou(), 100.0 * missed / dynamic_pixels);
  }
  std::fflush(stdout);
}

}  // namespace
}  // namespace roadscale

int main(int argc, char** argv) {
  std::vector<std::string> reuse_sizes = {"640x192", "1024x320"};
  int frames = 200;
  bool labelled = true;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--reuse-sizes" && i + 1 < argc) {
      reuse_sizes = roadscale::SplitCommas(argv[++i]);
    } else if (argument == "--frames" && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else if (argument == "--no-labelled") {
      labelled = false;
    } else {
      std::fprintf(stderr,
                   "usage: %s [--reuse-sizes 640x192,1024x320] [--frames 200] [--no-labelled]\n",
                   argv[0]);
      return 2;
    }
  }
  try {
    if (labelled) roadscale::LabelledImageIou();
    for (const std::string& size : reuse_sizes) roadscale::ReuseCost(size, frames);
  } catch (const roadscale::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
