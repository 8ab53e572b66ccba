// The road plane of frame pairs measured by aligning the road's pixels (AlignRoadPlane) on a
// rendered drive, against the truth: the motion from the ground-truth poses, the road mask
// from the rendered labels, and |t| / h compared with the true step over the true height.
//
//   roadscale_road_alignment_accuracy SEQUENCE_DIR [--gaps 1,2,3] [--every 3] [--prior F]
//                                     [--pitch-error-deg D] [--erosion PX] [--max-samples N]
//                                     [--max-lateral H] [--max-distance H]
//
// SEQUENCE_DIR is a `roadscale synth` sequence (image_0/, semantic/, road_planes.txt, and
// ../../poses/NN.txt). Pairs k, k + gap for every `every`-th k. --prior F: the alignment is
// told |t| / h times F (as the map would tell it; 0, the default: no prior, the whole range
// searched). --pitch-error-deg: the true rotation turned by that much in pitch first (the
// motion a map would give). --erosion: the road masks' erosion. --max-samples: road pixels per
// level. --max-lateral: road pixels only within H camera heights to either side. --max-distance:
// only within H camera heights ahead.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "roadscale/io/image_file.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/scale/road_plane_alignment.h"
#include "roadscale/segmentation/segmentation_masks.h"
#include "roadscale/synth/road_plane_file.h"
#include "roadscale/util/error.h"

namespace fs = std::filesystem;
using namespace roadscale;

namespace {

std::string FramePath(const fs::path& dir, const char* folder, int index) {
  char name[16];
  std::snprintf(name, sizeof(name), "%06d.png", index);
  return (dir / folder / name).string();
}

double Percentile(std::vector<double> values, double p) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(p * (values.size() - 1) + 0.5)];
}

std::vector<int> ParseList(const std::string& text) {
  std::vector<int> values;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    values.push_back(std::stoi(text.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) {
      std::fprintf(stderr,
                   "usage: %s SEQUENCE_DIR [--gaps 1,2,3] [--every 3] [--prior F] "
                   "[--pitch-error-deg D] [--erosion PX] [--max-samples N] [--max-lateral H] "
                   "[--max-distance H]\n",
                   argv[0]);
      return 2;
    }
    const fs::path dir = argv[1];
    std::vector<int> gaps = {1, 2, 3};
    int every = 3;
    double prior = 0.0;
    int max_samples = RoadPlaneAlignmentOptions().max_samples;
    double pitch_error_deg = 0.0;
    int erosion = RoadPlaneAlignmentOptions().mask_erosion_px;
    double max_lateral = RoadPlaneAlignmentOptions().max_lateral_offset;
    double max_distance = RoadPlaneAlignmentOptions().max_distance;
    for (int i = 2; i < argc; i += 2) {
      const std::string flag = argv[i];
      const bool known = flag == "--gaps" || flag == "--prior" || flag == "--pitch-error-deg" ||
                         flag == "--max-samples" || flag == "--erosion" || flag == "--every" ||
                         flag == "--max-lateral" || flag == "--max-distance";
      if (!known) throw Error("unknown option " + flag);
      if (i + 1 >= argc) throw Error("option " + flag + " needs a value");
      if (flag == "--gaps") {
        gaps = ParseList(argv[i + 1]);
      } else if (flag == "--prior") {
        prior = std::stod(argv[i + 1]);
      } else if (flag == "--pitch-error-deg") {
        pitch_error_deg = std::stod(argv[i + 1]);
      } else if (flag == "--max-samples") {
        max_samples = std::stoi(argv[i + 1]);
      } else if (flag == "--erosion") {
        erosion = std::stoi(argv[i + 1]);
      } else if (flag == "--max-lateral") {
        max_lateral = std::stod(argv[i + 1]);
      } else if (flag == "--max-distance") {
        max_distance = std::stod(argv[i + 1]);
      } else {
        every = std::stoi(argv[i + 1]);
      }
    }
    if (every < 1) throw Error("--every must be at least 1");
    for (int gap : gaps) {
      if (gap < 1) throw Error("--gaps must be positive frame counts");
    }
    const std::string sequence = dir.filename().string();
    const Trajectory truth = ReadKittiTrajectory(
        (dir.parent_path().parent_path() / "poses" / (sequence + ".txt")).string());
    const std::vector<synth::RoadPlaneRow> planes =
        synth::ReadRoadPlanes((dir / "road_planes.txt").string());
    PinholeCamera camera = KittiOdometryCamera();
    RoadPlaneAlignmentOptions options;
    options.mask_erosion_px = erosion;
    options.max_samples = max_samples;
    options.max_lateral_offset = max_lateral;
    options.max_distance = max_distance;
    std::printf(
        "gap | pairs | failed | median |error| %% | p90 |error| %% | mean error %% | "
        "median normal error deg | ms per pair\n");
    for (int gap : gaps) {
      std::vector<double> errors, abs_errors, normal_errors;
      int failed = 0, pairs = 0;
      double milliseconds = 0.0;
      for (size_t k = 0; k + gap < truth.size() && k + gap < planes.size(); k += every) {
        const size_t j = k + gap;
        const cv::Mat prev =
            ReadImageFile(FramePath(dir, "image_0", k), cv::IMREAD_GRAYSCALE, "image");
        const cv::Mat cur =
            ReadImageFile(FramePath(dir, "image_0", j), cv::IMREAD_GRAYSCALE, "image");
        const cv::Mat prev_road = LabelsInSet(
            ReadImageFile(FramePath(dir, "semantic", k), cv::IMREAD_GRAYSCALE, "labels"), {0});
        const cv::Mat cur_road = LabelsInSet(
            ReadImageFile(FramePath(dir, "semantic", j), cv::IMREAD_GRAYSCALE, "labels"), {0});
        Rigid3d cur_from_prev = truth.world_from_cam[j].inverse() * truth.world_from_cam[k];
        cur_from_prev.linear() =
            Eigen::AngleAxisd(pitch_error_deg * M_PI / 180.0, Eigen::Vector3d::UnitX()) *
            cur_from_prev.linear();
        const double step = cur_from_prev.translation().norm();
        if (step < 1e-3) continue;
        ++pairs;
        const auto start = std::chrono::steady_clock::now();
        const RoadPlaneAlignment fit =
            AlignRoadPlane(prev, cur, prev_road, cur_road, camera, cur_from_prev,
                           Eigen::Vector3d::UnitY(), prior * step / planes[k].height, options);
        milliseconds +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        if (!fit.ok) {
          ++failed;
          continue;
        }
        const double true_ratio = step / planes[k].height;
        const double error = (1.0 / fit.plane.height) / true_ratio - 1.0;
        errors.push_back(100.0 * error);
        abs_errors.push_back(100.0 * std::abs(error));
        normal_errors.push_back(
            std::acos(std::clamp(fit.plane.normal.dot(planes[k].normal), -1.0, 1.0)) * 180.0 /
            M_PI);
      }
      double mean = 0.0;
      for (double e : errors) mean += e / errors.size();
      std::printf("%d | %d | %d | %.2f | %.2f | %+.2f | %.2f | %.1f\n", gap, pairs, failed,
                  Percentile(abs_errors, 0.5), Percentile(abs_errors, 0.9), mean,
                  Percentile(normal_errors, 0.5), pairs > 0 ? milliseconds / pairs : 0.0);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roadscale_road_alignment_accuracy: %s\n", e.what());
    return 1;
  }
}
