// How well masks carried between segmented frames match fresh network masks, on the grey
// KITTI 00 frames (docs/benchmark-history.md, "Segmenting keyframes only").
//
//   build/bench/roadscale_mask_carrying_accuracy [--frames 200] [--size 512x256]
//
// The network segments every frame; the frontend tracks them as a run does. For each frame t
// and d = 1..4, frame t's masks are carried to frame t+d (road: the road homographies fitted
// to the tracks frame by frame; moving objects: moved with the road under them and grown,
// MaskCarryOptions' defaults) and compared with frame t+d's fresh masks: IoU pooled over the
// frames, and the share of frame t+d's (undilated) moving-object pixels the carried mask
// misses. The same for plain reuse (no carrying). Then the frames the keyframe schedule
// would segment (SegmentationSchedule at several thresholds) and the IoU of the masks
// every frame gets carried from the last segmented frame before it (what the frontend uses
// without latency; the scale stage has the segmented frames' own fresh masks).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "roadscale/frontend/mono_frontend.h"
#include "roadscale/io/kitti_calib.h"
#include "roadscale/pipeline/segmentation_schedule.h"
#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/segmentation/label_iou.h"
#include "roadscale/segmentation/mask_carrying.h"
#include "roadscale/segmentation/onnx_segmenter.h"
#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/util/error.h"
#include "roadscale/util/shared_data.h"

namespace roadscale {
namespace {

struct Missed {
  double missed = 0.0, total = 0.0;
  void Add(const cv::Mat& mask, const cv::Mat& labels) {
    const cv::Mat raw = LabelsInSet(labels, CityscapesDynamicTrainIds());
    missed += cv::countNonZero(raw & ~mask);
    total += cv::countNonZero(raw);
  }
  double Percent() const { return total > 0.0 ? 100.0 * missed / total : 0.0; }
};

void Run(int frames, const std::string& size) {
  const std::filesystem::path sequence = SharedDataDir() / "kitti/sequences/00";
  const PinholeCamera camera = ReadKittiCamera((sequence / "calib.txt").string(), 0, 1241, 376);
  OnnxSegmenter network(ReadSegmentationModel(std::string(ROADSCALE_SOURCE_DIR) +
                                              "/config/models/espnetv2_" + size + ".yaml"),
                        OnnxSegmenter::Options());
  MonoFrontend frontend(camera, FrontendOptions());
  const MaskCarryOptions carry;
  std::vector<SegmentationResult> fresh;
  std::vector<FrontendFrame> tracked;
  for (int t = 0; t < frames; ++t) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d", t);
    const std::string path = (sequence / "image_0" / (std::string(name) + ".png")).string();
    const cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
    if (image.empty()) throw Error(path + ": cannot read this frame");
    fresh.push_back(network.Segment(image, name));
    tracked.push_back(
        frontend.ProcessFrame(t, image, fresh.back().static_mask, fresh.back().dynamic_mask));
  }
  // The road homography of step t-1 -> t, with the road tracks picked by `road` (frame t-1).
  const auto step = [&](int t, const cv::Mat& road, Eigen::Matrix3d* last) {
    std::vector<Eigen::Vector2d> prev, cur;
    for (const Correspondence& c : tracked[t].correspondences) {
      prev.push_back(c.prev);
      cur.push_back(c.cur);
    }
    const std::optional<Eigen::Matrix3d> h = FitRoadHomography(prev, cur, road, carry);
    if (h) *last = *h;
    return h.has_value();
  };

  std::printf("ESPNetv2 %s on KITTI 00 frames 0..%d, masks of frame t at frame t+d\n", size.c_str(),
              frames - 1);
  std::printf(
      "  d | road IoU carried | reused | dynamic IoU carried | reused | dynamic missed "
      "carried | reused\n");
  for (const int d : {1, 2, 3, 4}) {
    PooledMaskIou road, road_reused, dynamic, dynamic_reused;
    Missed missed, missed_reused;
    for (int t = 0; t + d < frames; ++t) {
      Eigen::Matrix3d cur_from_t = Eigen::Matrix3d::Identity();
      Eigen::Matrix3d last = Eigen::Matrix3d::Identity();
      cv::Mat carried_road = fresh[t].road_mask;
      for (int k = t + 1; k <= t + d; ++k) {
        step(k, carried_road, &last);
        cur_from_t = last * cur_from_t;
        carried_road = CarryRoadMask(fresh[t].road_mask, cur_from_t);
      }
      const cv::Mat carried_dynamic = CarryDynamicMask(fresh[t].dynamic_mask, cur_from_t, d, carry);
      const SegmentationResult& now = fresh[t + d];
      road.Add(carried_road, now.road_mask);
      road_reused.Add(fresh[t].road_mask, now.road_mask);
      dynamic.Add(carried_dynamic, now.dynamic_mask);
      dynamic_reused.Add(fresh[t].dynamic_mask, now.dynamic_mask);
      missed.Add(carried_dynamic, now.labels);
      missed_reused.Add(fresh[t].dynamic_mask, now.labels);
    }
    std::printf(
        "  %d | %.3f            | %.3f  | %.3f               | %.3f  | %5.1f %%"
        "                | %.1f %%\n",
        d, road.Iou(), road_reused.Iou(), dynamic.Iou(), dynamic_reused.Iou(), missed.Percent(),
        missed_reused.Percent());
  }

  // The keyframe schedule at several parallax thresholds (the default: 30 px), and the masks
  // every frame gets carried from the last segmented frame before it.
  std::printf(
      "keyframe schedule: threshold | segmented | mean spacing | road IoU | dynamic "
      "IoU | dynamic missed\n");
  // (parallax px, tracked share): the back end's keyframes, then the default's neighbours.
  for (const auto& [parallax_px, tracked_share] :
       {std::pair{10.0, 0.5}, {30.0, 0.5}, {30.0, 0.3}, {30.0, 0.2}, {60.0, 0.3}}) {
    KeyframeSelectorOptions schedule_options = SegmentationScheduleOptions().keyframes;
    schedule_options.min_parallax_px = parallax_px;
    schedule_options.min_tracked_share = tracked_share;
    SegmentationSchedule schedule(camera, schedule_options);
    PooledMaskIou road, dynamic;
    Missed missed;
    int segmented = 0;
    std::vector<int> gaps;
    int last_segmented = 0;
    Eigen::Matrix3d cur_from_segmented = Eigen::Matrix3d::Identity();
    Eigen::Matrix3d last = Eigen::Matrix3d::Identity();
    cv::Mat carried_road;
    for (int t = 0; t < frames; ++t) {
      bool failed = false;
      if (t > 0) {
        failed = !step(t, carried_road, &last);
        cur_from_segmented = last * cur_from_segmented;
        carried_road = CarryRoadMask(fresh[last_segmented].road_mask, cur_from_segmented);
        const cv::Mat carried_dynamic = CarryDynamicMask(
            fresh[last_segmented].dynamic_mask, cur_from_segmented, t - last_segmented, carry);
        road.Add(carried_road, fresh[t].road_mask);
        dynamic.Add(carried_dynamic, fresh[t].dynamic_mask);
        missed.Add(carried_dynamic, fresh[t].labels);
      }
      if (schedule.Decide(tracked[t], failed)) {
        ++segmented;
        if (t > 0) gaps.push_back(t - last_segmented);
        last_segmented = t;
        cur_from_segmented.setIdentity();
        carried_road = fresh[t].road_mask;
      }
    }
    double mean_gap = 0.0;
    for (int gap : gaps) mean_gap += gap;
    std::printf("  %4.0f px, %.1f | %3d of %d (%4.1f %%) | %.2f frames | %.3f | %.3f | %4.1f %%\n",
                parallax_px, tracked_share, segmented, frames, 100.0 * segmented / frames,
                gaps.empty() ? 0.0 : mean_gap / gaps.size(), road.Iou(), dynamic.Iou(),
                missed.Percent());
  }
}

}  // namespace
}  // namespace roadscale

int main(int argc, char** argv) {
  int frames = 200;
  std::string size = "512x256";
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--frames" && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else if (argument == "--size" && i + 1 < argc) {
      size = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--frames 200] [--size 512x256]\n", argv[0]);
      return 2;
    }
  }
  try {
    roadscale::Run(frames, size);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  }
  return 0;
}
