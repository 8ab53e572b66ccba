// Accuracy of the road-plane scale (section III of the paper) on its own, without a frontend,
// and the paper's ablations, on the shared KITTI 00 frames and on synthetic street pairs:
//
//   build/bench/roadscale_scale_on_kitti [--frames 200] [--synthetic-pairs 200] [--csv FILE]
//       [--sequence SEQ_DIR --poses POSES_TXT] [--h0 1.65] [--min-parallax-deg D]
//       [--only TEXT] [--diagnose 1] [--alignment free|tangent] [--direction truth|images]
//       [--direction-pitch-deg D]
//
// --min-parallax-deg changes triangulation.min_parallax_deg in every configuration.
// --only TEXT runs only the configurations whose name contains TEXT.
// --direction images: each pair's rotation and translation direction refined on the pair's own
// tracks (5 degrees of freedom, Huber on the Sampson error, from the ground truth's motion):
// the images' own geometry, as a frontend would give it, with the true step length still
// judging the scale. Prints the median offset of the images' direction to the truth's.
// --alignment free|tangent (KITTI-layout sequences with a road mask): also each pair's road
// plane from the road's pixels (AlignRoadPlaneOrSearchAll, the keyframe back end's road
// alignment, default options; tangent: RoadPlaneAlignmentOptions::tangent_to_travel) on the
// same motion and the two frames' semantic masks, told the true |t| / h0 as
// the map would tell it; printed as median and mean error of h0 / h against the true step,
// and written to --csv as configuration "road alignment, semantic".
// --direction-pitch-deg D turns each pair's translation direction by D degrees about the
// camera's x axis (positive: towards the camera's -y, up) after the above: how much a
// direction error in pitch moves the road scale.
// --diagnose 1 (rendered sequences with depth/, semantic/ and road_planes.txt): for each
// "semantic" configuration, the KLT error of the road tracks against the true flow (from the
// rendered depth and the true motion), their triangulated against their rendered depth, and
// the fitted plane against the true plane and against the plane through the true positions
// of the same inliers (docs/benchmark-history.md, "Bias analysis").
// --segmentation-model YAML (e.g. config/models/espnetv2_512x256.yaml, from the repository
// root) segments each previous frame and uses the network's road mask as the "semantic" mask
// when the sequence has no semantic/ folder.
// --sequence/--poses run any KITTI-layout sequence instead of the shared KITTI 00 frames (a
// `roadscale synth` sequence, say); when it has a semantic/ folder (Cityscapes train ids, as
// `synth` writes), its road label (0) gives a third mask, "semantic".
//
// KITTI: the rotation and the translation DIRECTION of each frame pair come from the ground
// truth (poses/00.txt); tracks from a plain KLT (goodFeaturesToTrack + pyramidal Lucas-Kanade,
// forward-backward checked, and kept when their Sampson distance to the ground-truth epipolar
// geometry is below 1 px: the "inlier tracks" a frontend would give). h0 = 1.65 m, KITTI's
// documented camera height (never fitted). The per-frame error is s / |t_true| - 1.
// "corridor mask": a crude road mask without segmentation: the ground 1.65 m under a level
// camera, 4 m to either side of the camera's axis, 3 m to 40 m ahead, drawn into the image.
//
// Synthetic: independent street pairs (road 1.65 m below the camera with a random pitch of
// up to 2 degrees, walls, a parked car, points above the horizon), a step along the road that
// swings smoothly between 0.5 and 1.5 m (period 200 pairs, at most 1.6 m/s^2 at 10 Hz) with a turn
// of up to 2 degrees, 0.3 px of pixel noise; the mask there marks the road and the car (a
// segmentation that mistakes the car for road).
//
// Every configuration sees the same tracks. Errors are reported for the raw scale and for
// the filtered scale; "bias" is the mean signed error, "len" the path-length ratio
// sum(s) / sum(|t_true|) of the filtered scale.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "roadscale/frontend/sampson_refinement.h"
#include "roadscale/geometry/pinhole_camera.h"
#include "roadscale/io/kitti_calib.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/scale/road_model_check.h"
#include "roadscale/scale/road_plane_alignment.h"
#include "roadscale/scale/scale_estimator.h"
#include "roadscale/segmentation/make_segmenter.h"
#include "roadscale/testing/synthetic_road_scene.h"
#include "roadscale/util/error.h"
#include "roadscale/util/random.h"
#include "roadscale/util/shared_data.h"

namespace roadscale {
namespace {

// One frame pair's input to the scale module and the truth.
struct PairData {
  std::vector<Eigen::Vector2d> prev_pixels;
  std::vector<Eigen::Vector2d> cur_pixels;
  Rigid3d cur_from_prev;  // translation of unit length
  double true_step = 0.0;
  cv::Mat mask;           // the crude corridor mask, or the synthetic pairs' road mask
  cv::Mat semantic_mask;  // from the sequence's semantic labels (empty when it has none)
  // Rendered sequences only (depth/ and road_planes.txt): the true depth (z, metres; 0 when
  // unknown) and the road label of each previous pixel, and the previous frame's road plane.
  std::vector<double> true_depths;
  std::vector<bool> on_road;
  std::optional<Plane> true_plane;
  cv::Mat prev_image, cur_image;  // KITTI-layout sequences only
};

enum class MaskKind { kNone, kCorridor, kSemantic };

struct Configuration {
  std::string name;
  std::function<void(ScaleEstimatorOptions*)> change;
  MaskKind mask = MaskKind::kNone;
};

double Percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const double position = fraction * (values.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(values.size() - 1, below + 1);
  return values[below] + (position - below) * (values[above] - values[below]);
}

double Mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double value : values) sum += value;
  return values.empty() ? std::nan("") : sum / values.size();
}

double SampsonDistancePx(const Eigen::Matrix3d& fundamental, const Eigen::Vector2d& prev,
                         const Eigen::Vector2d& cur) {
  const Eigen::Vector3d a = prev.homogeneous();
  const Eigen::Vector3d b = cur.homogeneous();
  const Eigen::Vector3d fa = fundamental * a;
  const Eigen::Vector3d ftb = fundamental.transpose() * b;
  const double numerator = b.dot(fa);
  const double denominator = fa.head<2>().squaredNorm() + ftb.head<2>().squaredNorm();
  return std::abs(numerator) / std::sqrt(denominator);
}

Eigen::Matrix3d Fundamental(const Rigid3d& cur_from_prev, const PinholeCamera& camera) {
  const Eigen::Vector3d t = cur_from_prev.translation();
  Eigen::Matrix3d t_cross;
  t_cross << 0, -t.z(), t.y(), t.z(), 0, -t.x(), -t.y(), t.x(), 0;
  const Eigen::Matrix3d k_inv = camera.K().inverse();
  return k_inv.transpose() * t_cross * cur_from_prev.linear() * k_inv;
}

cv::Mat CorridorMask(const PinholeCamera& camera, double camera_height) {
  cv::Mat mask(camera.height, camera.width, CV_8UC1, cv::Scalar(0));
  std::vector<cv::Point> polygon;
  for (const Eigen::Vector3d& corner :
       {Eigen::Vector3d(-4.0, camera_height, 3.0), Eigen::Vector3d(-4.0, camera_height, 40.0),
        Eigen::Vector3d(4.0, camera_height, 40.0), Eigen::Vector3d(4.0, camera_height, 3.0)}) {
    const Eigen::Vector2d pixel = camera.Project(corner);
    polygon.emplace_back(cvRound(pixel.x()), cvRound(pixel.y()));
  }
  cv::fillConvexPoly(mask, polygon, cv::Scalar(255));
  return mask;
}

// Where each KITTI pair's rotation and translation direction come from.
struct PairMotion {
  bool from_images = false;  // refined on the pair's tracks, else the ground truth's
  double pitch_deg = 0.0;    // then turned by this about the camera's x axis
};

// The pair's motion refined on its tracks (normalised coordinates); returns the change of the
// translation direction's pitch and yaw, degrees.
Eigen::Vector2d RefineOnTracks(const PinholeCamera& camera, PairData* pair) {
  std::vector<Eigen::Vector2d> prev, cur;
  for (size_t i = 0; i < pair->prev_pixels.size(); ++i) {
    prev.push_back(camera.Unproject(pair->prev_pixels[i]).hnormalized());
    cur.push_back(camera.Unproject(pair->cur_pixels[i]).hnormalized());
  }
  const Eigen::Vector3d truth = pair->cur_from_prev.translation();
  const SampsonRefinementResult refined = RefineRelativePoseSampson(
      pair->cur_from_prev.linear(), truth, prev, cur, camera.fx, SampsonRefinementOptions{});
  pair->cur_from_prev = MakeRigid3d(refined.rotation, refined.direction);
  const auto degrees = [](double radians) { return radians * 180.0 / M_PI; };
  return {degrees(std::asin(refined.direction.y()) - std::asin(truth.y())),
          degrees(std::asin(refined.direction.x()) - std::asin(truth.x()))};
}

std::vector<PairData> KittiPairs(const std::string& sequence_dir, const std::string& poses,
                                 int num_frames, double camera_height,
                                 const std::string& segmentation_model, const PairMotion& motion,
                                 PinholeCamera* camera) {
  const Trajectory truth = ReadKittiTrajectory(poses);
  const std::string image_dir = sequence_dir + "/image_0";
  const std::string semantic_dir = sequence_dir + "/semantic";
  const bool has_semantic = std::filesystem::is_directory(semantic_dir);
  const std::string depth_dir = sequence_dir + "/depth";
  const bool has_depth = std::filesystem::is_directory(depth_dir);
  std::map<int, Plane> true_planes;
  {
    std::ifstream planes(sequence_dir + "/road_planes.txt");
    std::string line;
    while (std::getline(planes, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      int index = 0;
      Plane plane;
      fields >> index >> plane.normal.x() >> plane.normal.y() >> plane.normal.z() >> plane.height;
      if (fields) true_planes[index] = plane;
    }
  }
  std::unique_ptr<Segmenter> segmenter;
  if (!has_semantic && !segmentation_model.empty()) {
    SegmentationOptions segmentation;
    segmentation.model = segmentation_model;
    segmenter = MakeSegmenter(segmentation);
  }
  std::vector<PairData> pairs;
  std::vector<double> pitch_offsets, yaw_offsets;
  cv::Mat prev_image;
  for (int frame = 0; frame < num_frames && frame < static_cast<int>(truth.size()); ++frame) {
    char name[32];
    std::snprintf(name, sizeof(name), "/%06d.png", frame);
    const cv::Mat image = cv::imread(image_dir + name, cv::IMREAD_GRAYSCALE);
    if (image.empty()) ThrowFileError(image_dir + name, "cannot read the image");
    if (frame == 0) {
      *camera = ReadKittiCamera(sequence_dir + "/calib.txt", 0, image.cols, image.rows);
      prev_image = image;
      continue;
    }
    PairData pair;
    if (has_semantic) {
      char previous[32];
      std::snprintf(previous, sizeof(previous), "/%06d.png", frame - 1);
      const cv::Mat labels = cv::imread(semantic_dir + previous, cv::IMREAD_UNCHANGED);
      if (labels.empty()) ThrowFileError(semantic_dir + previous, "cannot read the labels");
      pair.semantic_mask = labels == 0;
    } else if (segmenter) {
      char previous[32];
      std::snprintf(previous, sizeof(previous), "%06d", frame - 1);
      pair.semantic_mask = segmenter->Segment(prev_image, previous).road_mask;
    }
    const Rigid3d cur_from_prev =
        truth.world_from_cam[frame].inverse() * truth.world_from_cam[frame - 1];
    pair.true_step = cur_from_prev.translation().norm();
    pair.cur_from_prev = MakeRigid3d(NearestRotation(cur_from_prev.linear()),
                                     cur_from_prev.translation() / pair.true_step);
    const Eigen::Matrix3d fundamental = Fundamental(pair.cur_from_prev, *camera);

    std::vector<cv::Point2f> corners;
    cv::goodFeaturesToTrack(prev_image, corners, 3000, 0.005, 7.0);
    std::vector<cv::Point2f> tracked;
    std::vector<cv::Point2f> back;
    std::vector<uchar> status;
    std::vector<uchar> back_status;
    std::vector<float> error;
    const cv::Size window(21, 21);
    cv::calcOpticalFlowPyrLK(prev_image, image, corners, tracked, status, error, window, 3);
    cv::calcOpticalFlowPyrLK(image, prev_image, tracked, back, back_status, error, window, 3);
    for (size_t i = 0; i < corners.size(); ++i) {
      if (!status[i] || !back_status[i]) continue;
      if (cv::norm(back[i] - corners[i]) > 0.5) continue;
      const Eigen::Vector2d prev(corners[i].x, corners[i].y);
      const Eigen::Vector2d cur(tracked[i].x, tracked[i].y);
      if (!camera->IsInside(cur)) continue;
      if (SampsonDistancePx(fundamental, prev, cur) > 1.0) continue;
      pair.prev_pixels.push_back(prev);
      pair.cur_pixels.push_back(cur);
    }
    if (motion.from_images) {
      const Eigen::Vector2d offset = RefineOnTracks(*camera, &pair);
      pitch_offsets.push_back(offset.x());
      yaw_offsets.push_back(offset.y());
    }
    if (motion.pitch_deg != 0.0) {
      const Eigen::AngleAxisd turn(motion.pitch_deg * M_PI / 180.0, Eigen::Vector3d::UnitX());
      pair.cur_from_prev =
          MakeRigid3d(pair.cur_from_prev.linear(), turn * pair.cur_from_prev.translation());
    }
    if (has_depth) {
      char previous[32];
      std::snprintf(previous, sizeof(previous), "/%06d.png", frame - 1);
      const cv::Mat depth = cv::imread(depth_dir + previous, cv::IMREAD_UNCHANGED);
      if (depth.type() != CV_16UC1) ThrowFileError(depth_dir + previous, "expected 16-bit depth");
      for (const Eigen::Vector2d& pixel : pair.prev_pixels) {
        const int x = std::clamp(static_cast<int>(std::lround(pixel.x())), 0, depth.cols - 1);
        const int y = std::clamp(static_cast<int>(std::lround(pixel.y())), 0, depth.rows - 1);
        pair.true_depths.push_back(depth.at<uint16_t>(y, x) / 256.0);
        pair.on_road.push_back(!pair.semantic_mask.empty() && pair.semantic_mask.at<uchar>(y, x));
      }
      const auto plane = true_planes.find(frame - 1);
      if (plane != true_planes.end()) pair.true_plane = plane->second;
    }
    pair.prev_image = prev_image;
    pair.cur_image = image;
    pairs.push_back(std::move(pair));
    prev_image = image;
  }
  const cv::Mat corridor = CorridorMask(*camera, camera_height);
  for (PairData& pair : pairs) pair.mask = corridor;
  if (motion.from_images) {
    std::printf(
        "\nThe images' translation direction against the ground truth's, median over %zu "
        "pairs: pitch %+.3f deg, yaw %+.3f deg\n",
        pitch_offsets.size(), Percentile(pitch_offsets, 0.5), Percentile(yaw_offsets, 0.5));
  }
  return pairs;
}

std::vector<PairData> SyntheticPairs(int count) {
  Rng rng(2024);
  const PinholeCamera camera = KittiOdometryCamera();
  std::vector<PairData> pairs;
  for (int i = 0; i < count; ++i) {
    const double pitch = rng.Uniform(-2.0, 2.0) * M_PI / 180.0;
    testing::SceneOptions scene;
    scene.road = Plane{Eigen::Vector3d(0.0, std::cos(pitch), std::sin(pitch)), 1.65};
    scene.seed = 1000 + i;
    // The speed changes smoothly, as a car's does (the filter assumes so): 0.5 to 1.5 m.
    const double step = 1.0 + 0.5 * std::sin(2.0 * M_PI * i / 200.0);
    const double yaw = rng.Uniform(-2.0, 2.0) * M_PI / 180.0;
    const Rigid3d motion = testing::DriveAlongRoad(scene.road, step, yaw);
    const testing::TwoViewObservations observations =
        testing::ObserveTwoViews(testing::MakeStreetScene(scene), motion, camera, 0.3, 5000 + i);
    PairData pair;
    pair.prev_pixels = observations.prev_pixels;
    pair.cur_pixels = observations.cur_pixels;
    pair.cur_from_prev = MakeRigid3d(motion.linear(), motion.translation() / step);
    pair.true_step = step;
    pair.mask = testing::MaskFromLabels(observations, camera,
                                        {testing::SceneLabel::kRoad, testing::SceneLabel::kCar}, 4);
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

struct Summary {
  std::vector<double> raw_errors;  // frames with a scale
  std::vector<double> filtered_errors;
  double estimated_length = 0.0;
  double true_length = 0.0;
  int frames_without_scale = 0;
  int held = 0;
  double total_ms = 0.0;
  std::vector<double> ms;
};

Summary Run(const std::vector<PairData>& pairs, const PinholeCamera& camera,
            const Configuration& configuration, int first_counted, std::ofstream* csv,
            const std::string& data_name, double camera_height) {
  ScaleEstimatorOptions options;
  options.camera_height = camera_height;
  configuration.change(&options);
  ScaleEstimator estimator(camera, options);
  Summary summary;
  const cv::Mat no_mask;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const PairData& pair = pairs[i];
    const auto start = std::chrono::steady_clock::now();
    const cv::Mat& mask = configuration.mask == MaskKind::kCorridor   ? pair.mask
                          : configuration.mask == MaskKind::kSemantic ? pair.semantic_mask
                                                                      : no_mask;
    const ScaleEstimate estimate =
        estimator.Estimate(pair.prev_pixels, pair.cur_pixels, pair.cur_from_prev, mask);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    summary.ms.push_back(ms);
    if (csv != nullptr) {
      *csv << data_name << ',' << configuration.name << ',' << i + 1 << ','
           << ScaleStatusName(estimate.status) << ',' << pair.true_step << ',' << estimate.raw_scale
           << ',' << estimate.scale << ',' << estimate.num_tracks << ','
           << estimate.num_triangulated << ',' << estimate.num_preselected << ','
           << estimate.num_after_vote << ',' << estimate.num_after_road_model << ','
           << estimate.num_ransac_inliers << ',' << estimate.plane.height << ','
           << estimate.plane.PitchRad() * 180.0 / M_PI << ','
           << estimate.plane.RollRad() * 180.0 / M_PI << ',' << ms << '\n';
    }
    if (static_cast<int>(i) < first_counted) continue;
    if (estimate.status != ScaleStatus::kOk) ++summary.held;
    if (!estimate.has_scale) {
      ++summary.frames_without_scale;
      continue;
    }
    summary.raw_errors.push_back(estimate.raw_scale / pair.true_step - 1.0);
    summary.filtered_errors.push_back(estimate.scale / pair.true_step - 1.0);
    summary.estimated_length += estimate.scale;
    summary.true_length += pair.true_step;
  }
  return summary;
}

void PrintRow(const std::string& name, const Summary& summary) {
  std::vector<double> raw_abs;
  std::vector<double> filtered_abs;
  for (double e : summary.raw_errors) raw_abs.push_back(std::abs(e));
  for (double e : summary.filtered_errors) filtered_abs.push_back(std::abs(e));
  std::printf("| %-34s | %5.2f | %5.2f | %+6.2f | %5.2f | %5.2f | %+6.2f | %6.4f | %3d | %4.2f |\n",
              name.c_str(), 100 * Percentile(raw_abs, 0.5), 100 * Percentile(raw_abs, 0.9),
              100 * Mean(summary.raw_errors), 100 * Percentile(filtered_abs, 0.5),
              100 * Percentile(filtered_abs, 0.9), 100 * Mean(summary.filtered_errors),
              summary.estimated_length / summary.true_length, summary.held, Mean(summary.ms));
}

// The road alignment of each pair whose two frames have a semantic road mask (the next pair's
// previous mask is this pair's current one), against the true step.
void PrintAlignment(const std::vector<PairData>& pairs, const PinholeCamera& camera,
                    const RoadPlaneAlignmentOptions& options, int first_counted, std::ofstream* csv,
                    const std::string& data_name, double camera_height) {
  std::vector<double> errors;
  int attempted = 0;
  for (size_t k = static_cast<size_t>(first_counted); k + 1 < pairs.size(); ++k) {
    const PairData& pair = pairs[k];
    const cv::Mat& cur_mask = pairs[k + 1].semantic_mask;
    if (pair.semantic_mask.empty() || cur_mask.empty() || pair.true_step <= 0.0) continue;
    ++attempted;
    const std::optional<Eigen::Vector3d> normal =
        ExpectedRoadNormal(pair.cur_from_prev, RoadModelCheckOptions{});
    const RoadPlaneAlignment alignment = AlignRoadPlaneOrSearchAll(
        pair.prev_image, pair.cur_image, pair.semantic_mask, cur_mask, camera, pair.cur_from_prev,
        normal.value_or(Eigen::Vector3d::UnitY()), pair.true_step / camera_height, options);
    const double scale = alignment.ok ? camera_height / alignment.plane.height : std::nan("");
    if (alignment.ok) errors.push_back(scale / pair.true_step - 1.0);
    if (csv != nullptr) {
      *csv << data_name << ",road alignment, semantic," << k + 1 << ','
           << (alignment.ok ? "ok" : "no plane") << ',' << pair.true_step << ',' << scale << ','
           << scale << ",,,,,,," << alignment.plane.height << ",,,\n";
    }
  }
  std::vector<double> absolute;
  for (double error : errors) absolute.push_back(std::abs(error));
  std::printf(
      "\nRoad alignment, semantic (pairs from %d): %zu of %d pairs aligned, median |error| "
      "%.2f %%, median error %+.2f %%, mean error %+.2f %%\n",
      first_counted + 1, errors.size(), attempted, 100.0 * Percentile(absolute, 0.5),
      100.0 * Percentile(errors, 0.5), 100.0 * Mean(errors));
}

void PrintTable(const std::string& title, const std::vector<PairData>& pairs,
                const PinholeCamera& camera, const std::vector<Configuration>& configurations,
                int first_counted, std::ofstream* csv, const std::string& data_name,
                double camera_height) {
  int tracks = 0;
  for (const PairData& pair : pairs) tracks += static_cast<int>(pair.prev_pixels.size());
  std::printf("\n%s (%zu frame pairs, %d tracks a pair on average, counted from pair %d)\n\n",
              title.c_str(), pairs.size(), tracks / std::max<int>(1, pairs.size()),
              first_counted + 1);
  std::printf(
      "| %-34s | raw med%% | raw p90%% | raw bias%% | filt med%% | filt p90%% | "
      "filt bias%% | len ratio | held | ms |\n",
      "configuration");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  const bool has_semantic = !pairs.empty() && !pairs.front().semantic_mask.empty();
  for (const Configuration& configuration : configurations) {
    if (configuration.mask == MaskKind::kSemantic && !has_semantic) continue;
    PrintRow(configuration.name,
             Run(pairs, camera, configuration, first_counted, csv, data_name, camera_height));
  }
}

// Where the bias of a rendered sequence comes from (needs depth/, semantic/ and
// road_planes.txt): for every pair, the triangulated depth of the road-labelled tracks against
// the rendered depth, binned by true depth; and for the configuration's RANSAC inliers, the
// plane fitted to their triangulated points against the plane fitted to their TRUE points
// (the same tracks at the rendered depth) and against the true road plane. "sel" isolates
// what the selection picked (not road, or road off the tangent plane), "tri" adds the
// triangulation.
void Diagnose(const std::vector<PairData>& pairs, const PinholeCamera& camera,
              const Configuration& configuration, double camera_height) {
  if (pairs.empty() || pairs.front().true_depths.empty()) return;
  ScaleEstimatorOptions options;
  options.camera_height = camera_height;
  configuration.change(&options);
  ScaleEstimator estimator(camera, options);
  const cv::Mat no_mask;
  const std::vector<double> edges = {0, 6, 9, 12, 16, 20, 25, 30, 40, 60, 1e9};
  const size_t bins = edges.size() - 1;
  std::vector<std::vector<double>> all_errors(bins), inlier_errors(bins);
  // KLT's current pixel minus the true one (from the rendered depth and the true motion),
  // along x and y, for road and for other tracks.
  std::vector<std::vector<double>> road_dx(bins), road_dy(bins), other_dx(bins), other_dy(bins);
  std::vector<double> h_tri, h_sel, h_scale, pitch_diff, roll_diff, true_dist_sel, z_inliers;
  for (const PairData& pair : pairs) {
    const cv::Mat& mask = configuration.mask == MaskKind::kCorridor   ? pair.mask
                          : configuration.mask == MaskKind::kSemantic ? pair.semantic_mask
                                                                      : no_mask;
    const ScaleEstimate estimate =
        estimator.Estimate(pair.prev_pixels, pair.cur_pixels, pair.cur_from_prev, mask);
    const TriangulatedPoints points = TriangulateUnitBaseline(
        pair.prev_pixels, pair.cur_pixels, pair.cur_from_prev, camera, options.triangulation);
    std::vector<int> point_of_track(pair.prev_pixels.size(), -1);
    for (size_t k = 0; k < points.track_indices.size(); ++k) {
      point_of_track[points.track_indices[k]] = static_cast<int>(k);
    }
    const auto bin_of = [&](double z) {
      size_t b = 0;
      while (b + 1 < bins && z >= edges[b + 1]) ++b;
      return b;
    };
    for (size_t t = 0; t < pair.prev_pixels.size(); ++t) {
      if (pair.true_depths[t] <= 0.0) continue;
      const Eigen::Vector3d ray = camera.Unproject(pair.prev_pixels[t]);
      const Eigen::Vector3d in_cur =
          pair.cur_from_prev.linear() * (ray / ray.z() * pair.true_depths[t]) +
          pair.cur_from_prev.translation() * pair.true_step;
      const Eigen::Vector2d error = pair.cur_pixels[t] - camera.Project(in_cur);
      const size_t b = bin_of(pair.true_depths[t]);
      if (!pair.on_road[t]) continue;
      // Road tracks whose KLT window (21 x 21) is all road, and the others.
      const cv::Rect window(static_cast<int>(std::lround(pair.prev_pixels[t].x())) - 10,
                            static_cast<int>(std::lround(pair.prev_pixels[t].y())) - 10, 21, 21);
      const cv::Rect clipped =
          window & cv::Rect(0, 0, pair.semantic_mask.cols, pair.semantic_mask.rows);
      const bool pure = clipped.area() == window.area() &&
                        cv::countNonZero(pair.semantic_mask(clipped)) == window.area();
      (pure ? road_dx : other_dx)[b].push_back(error.x());
      (pure ? road_dy : other_dy)[b].push_back(error.y());
    }
    for (size_t t = 0; t < pair.prev_pixels.size(); ++t) {
      const int k = point_of_track[t];
      if (k < 0 || !pair.on_road[t] || pair.true_depths[t] <= 0.0) continue;
      all_errors[bin_of(pair.true_depths[t])].push_back(
          points.points[k].z() * pair.true_step / pair.true_depths[t] - 1.0);
    }
    if (estimate.status != ScaleStatus::kOk || !pair.true_plane) continue;
    std::vector<Eigen::Vector3d> tri, truth;
    for (int t : estimate.road_track_indices) {
      if (pair.true_depths[t] <= 0.0) continue;
      const int k = point_of_track[t];
      tri.push_back(points.points[k] * pair.true_step);
      const Eigen::Vector3d ray = camera.Unproject(pair.prev_pixels[t]);
      truth.push_back(ray / ray.z() * pair.true_depths[t]);
      inlier_errors[bin_of(pair.true_depths[t])].push_back(tri.back().z() / truth.back().z() - 1.0);
      true_dist_sel.push_back(pair.true_plane->SignedDistance(truth.back()));
      z_inliers.push_back(truth.back().z());
    }
    std::vector<int> all(tri.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    const auto fit_tri = FitPlaneLeastSquares(tri, all, pair.true_plane->normal);
    const auto fit_sel = FitPlaneLeastSquares(truth, all, pair.true_plane->normal);
    if (!fit_tri || !fit_sel) continue;
    h_scale.push_back(estimate.plane.height * pair.true_step / pair.true_plane->height - 1.0);
    h_tri.push_back(fit_tri->height / pair.true_plane->height - 1.0);
    h_sel.push_back(fit_sel->height / pair.true_plane->height - 1.0);
    pitch_diff.push_back((estimate.plane.PitchRad() - pair.true_plane->PitchRad()) * 180 / M_PI);
    roll_diff.push_back((estimate.plane.RollRad() - pair.true_plane->RollRad()) * 180 / M_PI);
  }
  std::printf("\nBias diagnosis, %s (%zu fitted pairs)\n\n", configuration.name.c_str(),
              h_scale.size());
  std::printf(
      "| true depth m | road tracks | med depth err %% | mean %% | inliers | med %% | mean %% |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (size_t b = 0; b < bins; ++b) {
    std::printf("| %g-%g | %zu | %+.2f | %+.2f | %zu | %+.2f | %+.2f |\n", edges[b], edges[b + 1],
                all_errors[b].size(), 100 * Percentile(all_errors[b], 0.5),
                100 * Mean(all_errors[b]), inlier_errors[b].size(),
                100 * Percentile(inlier_errors[b], 0.5), 100 * Mean(inlier_errors[b]));
  }
  std::printf(
      "\n| true depth m | road tracks, window all road | med dx px | med dy px | road tracks, "
      "window not all road | med dx | med dy |\n|---|---|---|---|---|---|---|\n");
  for (size_t b = 0; b < bins; ++b) {
    std::printf("| %g-%g | %zu | %+.3f | %+.3f | %zu | %+.3f | %+.3f |\n", edges[b], edges[b + 1],
                road_dx[b].size(), Percentile(road_dx[b], 0.5), Percentile(road_dy[b], 0.5),
                other_dx[b].size(), Percentile(other_dx[b], 0.5), Percentile(other_dy[b], 0.5));
  }
  std::printf(
      "\nplane height / true h - 1 (mean, median %%): estimator %+.2f %+.2f; LS on triangulated "
      "inliers %+.2f %+.2f; LS on the inliers' true points %+.2f %+.2f\n",
      100 * Mean(h_scale), 100 * Percentile(h_scale, 0.5), 100 * Mean(h_tri),
      100 * Percentile(h_tri, 0.5), 100 * Mean(h_sel), 100 * Percentile(h_sel, 0.5));
  std::printf("plane pitch - true pitch (mean, median deg): %+.3f %+.3f; roll %+.3f %+.3f\n",
              Mean(pitch_diff), Percentile(pitch_diff, 0.5), Mean(roll_diff),
              Percentile(roll_diff, 0.5));
  std::printf(
      "inliers' true distance to the true plane (mean, median cm): %+.2f %+.2f; "
      "inliers' true depth median %.1f m, p90 %.1f m\n",
      100 * Mean(true_dist_sel), 100 * Percentile(true_dist_sel, 0.5), Percentile(z_inliers, 0.5),
      Percentile(z_inliers, 0.9));
}

std::vector<Configuration> Configurations() {
  using Options = ScaleEstimatorOptions;
  const auto none = [](Options*) {};
  std::vector<Configuration> list;
  for (MaskKind mask : {MaskKind::kNone, MaskKind::kCorridor, MaskKind::kSemantic}) {
    const std::string suffix = mask == MaskKind::kNone       ? ""
                               : mask == MaskKind::kCorridor ? ", mask"
                                                             : ", semantic";
    list.push_back({"paper default" + suffix, none, mask});
    list.push_back({"roadscale default (pixel refit)" + suffix,
                    [](Options* o) { o->homography_refit = true; }, mask});
    list.push_back({"no selection (RANSAC only)" + suffix,
                    [](Options* o) {
                      o->use_depth_vote = false;
                      o->use_road_model_check = false;
                    },
                    mask});
    list.push_back({"RM (no vote)" + suffix, [](Options* o) { o->use_depth_vote = false; }, mask});
  }
  const MaskKind corridor = MaskKind::kCorridor;
  list.push_back({"vote per edge, mask",
                  [](Options* o) {
                    o->depth_vote.edge_visit = DepthConsistencyVoteOptions::EdgeVisit::kPerEdge;
                  },
                  corridor});
  list.push_back(
      {"vote beta_a = 0, mask", [](Options* o) { o->depth_vote.min_vote = 0; }, corridor});
  list.push_back(
      {"fixed camera pitch 0, mask",
       [](Options* o) { o->road_model.reference = RoadModelCheckOptions::Reference::kFixedPitch; },
       corridor});
  list.push_back({"filter sigma 3 + clamp 0.3, mask",
                  [](Options* o) {
                    o->filter.gaussian_sigma = 3.0;
                    o->filter.max_change_per_frame = 0.3;
                  },
                  corridor});
  list.push_back({"no filter, mask", [](Options* o) { o->use_filter = false; }, corridor});
  return list;
}

int Main(int argc, char** argv) {
  int frames = 200;
  int synthetic_pairs = 200;
  std::string csv_path;
  const std::filesystem::path kitti = SharedDataDir() / "kitti";
  std::string sequence_dir = (kitti / "sequences/00").string();
  std::string poses = (kitti / "poses/00.txt").string();
  bool own_sequence = false;
  double camera_height = 1.65;
  double min_parallax_deg = TriangulationOptions().min_parallax_deg;
  std::string segmentation_model;
  bool diagnose = false;
  std::optional<RoadPlaneAlignmentOptions> alignment;
  PairMotion motion;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw Error("option " + flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--frames") {
      frames = std::stoi(value);
    } else if (flag == "--synthetic-pairs") {
      synthetic_pairs = std::stoi(value);
    } else if (flag == "--csv") {
      csv_path = value;
    } else if (flag == "--sequence") {
      sequence_dir = value;
      own_sequence = true;
    } else if (flag == "--poses") {
      poses = value;
    } else if (flag == "--h0") {
      camera_height = std::stod(value);
    } else if (flag == "--min-parallax-deg") {
      min_parallax_deg = std::stod(value);
    } else if (flag == "--only") {
      only = value;
    } else if (flag == "--diagnose") {
      diagnose = value == "1";
    } else if (flag == "--segmentation-model") {
      segmentation_model = value;
    } else if (flag == "--alignment") {
      if (value != "free" && value != "tangent") {
        throw Error("--alignment must be free or tangent (found " + value + ")");
      }
      alignment.emplace();
      alignment->tangent_to_travel = value == "tangent";
    } else if (flag == "--direction") {
      if (value != "truth" && value != "images") {
        throw Error("--direction must be truth or images (found " + value + ")");
      }
      motion.from_images = value == "images";
    } else if (flag == "--direction-pitch-deg") {
      motion.pitch_deg = std::stod(value);
    } else {
      throw Error(
          "unknown option " + flag +
          " (expected --frames N, --synthetic-pairs N, --csv FILE, --sequence DIR, "
          "--poses FILE, --h0 METRES, --min-parallax-deg D, --segmentation-model YAML, "
          "--only TEXT, --diagnose 1, --alignment free|tangent, --direction truth|images or "
          "--direction-pitch-deg D)");
    }
  }
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    if (!csv) ThrowFileError(csv_path, "cannot write");
    csv << "data,configuration,pair,status,true_step,raw_scale,scale,tracks,triangulated,"
           "preselected,after_vote,after_road_model,inliers,plane_h,plane_pitch_deg,"
           "plane_roll_deg,ms\n";
  }
  std::ofstream* csv_out = csv_path.empty() ? nullptr : &csv;
  std::vector<Configuration> configurations;
  for (Configuration& configuration : Configurations()) {
    if (configuration.name.find(only) != std::string::npos) {
      configurations.push_back(std::move(configuration));
    }
  }
  for (Configuration& configuration : configurations) {
    const auto change = configuration.change;
    configuration.change = [change, min_parallax_deg](ScaleEstimatorOptions* options) {
      options->triangulation.min_parallax_deg = min_parallax_deg;
      // Every row is the paper's pipeline (its least-squares plane) unless it says otherwise.
      options->homography_refit = false;
      change(options);
    };
  }

  if (synthetic_pairs > 0) {
    PrintTable("Synthetic street pairs", SyntheticPairs(synthetic_pairs), KittiOdometryCamera(),
               configurations, 0, csv_out, "synthetic", 1.65);
  }
  if (frames > 1) {
    PinholeCamera camera;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<PairData> pairs =
        KittiPairs(sequence_dir, poses, frames, camera_height, segmentation_model, motion, &camera);
    std::printf("\nKLT tracking of %d frames of %s: %.1f s\n", frames, sequence_dir.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const std::string direction =
        std::string(motion.from_images ? ", the images' motion direction"
                                       : ", ground-truth motion direction") +
        (motion.pitch_deg != 0.0 ? " turned in pitch" : "");
    PrintTable((own_sequence ? sequence_dir : std::string("KITTI 00")) + direction, pairs, camera,
               configurations, 0, csv_out, own_sequence ? "sequence" : "kitti", camera_height);
    // Pairs 1-13 of KITTI 00: the ground truth's constant 0.860 m a frame while the car
    // accelerates.
    for (const Configuration& configuration : configurations) {
      if (diagnose && configuration.mask == MaskKind::kSemantic) {
        Diagnose(pairs, camera, configuration, camera_height);
      }
    }
    const std::string data_name = own_sequence ? "sequence" : "kitti";
    if (alignment) PrintAlignment(pairs, camera, *alignment, 0, csv_out, data_name, camera_height);
    if (alignment && !own_sequence) {
      PrintAlignment(pairs, camera, *alignment, 13, nullptr, data_name, camera_height);
    }
    if (!own_sequence) {
      PrintTable("KITTI 00 without the ground truth's constant-speed pairs 1-13", pairs, camera,
                 configurations, 13, nullptr, "kitti", camera_height);
    }
  }
  return 0;
}

}  // namespace
}  // namespace roadscale

int main(int argc, char** argv) {
  try {
    return roadscale::Main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roadscale_scale_on_kitti: error: %s\n", e.what());
    return 1;
  }
}
