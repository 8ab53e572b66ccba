// The sequential pipeline with the oracle scale on a short rendered street scene, compared
// frame by frame with the scene's exact poses. Rendering makes it slow (label `slow`).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include "roadscale/geometry/angles.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/pipeline/oracle_scale_source.h"
#include "roadscale/pipeline/road_scale_source.h"
#include "roadscale/pipeline/run_pipeline.h"
#include "roadscale/pipeline/sequential_pipeline.h"
#include "roadscale/segmentation/label_image_segmenter.h"
#include "roadscale/synth/scene_writer.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/testing/late_oracle.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// The frame-to-frame host, whose steps are the scale sources' lengths.
PipelineOptions FrameToFrame() {
  PipelineOptions options;
  options.mapping.mode = MappingOptions::Mode::kFrameToFrame;
  return options;
}

// Renders a preset's drive of `frames` frames into `dir`, only its first `written_frames`
// (0: all); the options that open them.
FrameSourceOptions RenderDrive(const std::string& preset, int frames, const testing::TempDir& dir,
                               int seed = 0, int written_frames = 0) {
  synth::SceneOptions scene_options = synth::PresetSceneOptions(preset);
  if (seed > 0) scene_options.seed = seed;
  synth::SyntheticScene scene(scene_options, frames);
  synth::SceneWriterOptions writer;
  writer.out_dir = dir.path().string();
  writer.max_frames = written_frames;
  synth::WriteSyntheticSequence(scene, writer);
  FrameSourceOptions source_options;
  source_options.input = (dir.path() / "sequences" / "00").string();
  source_options.type = FrameSourceType::kKitti;
  return source_options;
}

TEST(SequentialPipelineSynthetic, OracleScaleFollowsTheTrueMotionOfAnUrbanScene) {
  constexpr int kFrames = 25;
  testing::TempDir dir;

  const FrameSourceOptions source_options = RenderDrive("urban", kFrames, dir);
  const auto source = OpenFrameSource(source_options);
  ASSERT_NE(source->ground_truth(), nullptr);
  const Trajectory gt = *source->ground_truth();
  OracleScaleSource oracle(gt);
  const std::string out = dir.File("run");
  const RunSummary summary = RunSequentialPipeline(*source, oracle, FrameToFrame(), out);
  EXPECT_EQ(summary.frames, static_cast<size_t>(kFrames));
  EXPECT_EQ(summary.motion_frames, static_cast<size_t>(kFrames - 1));

  const Trajectory est = ReadKittiTrajectory(out + "/poses_kitti.txt");
  ASSERT_EQ(est.size(), static_cast<size_t>(kFrames));
  std::vector<double> direction_errors;
  double path = 0.0;
  for (int k = 1; k < kFrames; ++k) {
    const Rigid3d gt_step = gt.world_from_cam[k].inverse() * gt.world_from_cam[k - 1];
    const Rigid3d est_step = est.world_from_cam[k].inverse() * est.world_from_cam[k - 1];
    // Measured on 200 frames of this preset: max 0.03 deg, direction median 0.18 deg.
    EXPECT_LT(RotationAngle(est_step.linear().transpose() * gt_step.linear()) * kDegreesPerRadian,
              0.1)
        << "frame " << k;
    EXPECT_NEAR(est_step.translation().norm(), gt_step.translation().norm(), 1e-6);
    const double c = est_step.translation().normalized().dot(gt_step.translation().normalized());
    direction_errors.push_back(std::acos(std::clamp(c, -1.0, 1.0)) * kDegreesPerRadian);
    EXPECT_LT(direction_errors.back(), 2.0) << "frame " << k;
    path += gt_step.translation().norm();
  }
  std::nth_element(direction_errors.begin(), direction_errors.begin() + direction_errors.size() / 2,
                   direction_errors.end());
  EXPECT_LT(direction_errors[direction_errors.size() / 2], 0.4);
  // The end point: the oracle scale leaves only the frontend's drift.
  const double drift =
      (est.world_from_cam.back().translation() - gt.world_from_cam.back().translation()).norm();
  EXPECT_GT(path, 10.0);
  EXPECT_LT(drift, 0.02 * path);
}

// The oracle's lengths times `factor`: a scale source gone wrong (h0 in the wrong unit).
class ScaledOracle : public ScaleSource {
 public:
  ScaledOracle(Trajectory ground_truth, double factor)
      : oracle_(std::move(ground_truth)), factor_(factor) {}
  std::string Name() const override { return "scaled oracle"; }
  ScaleResult StepLength(const ScaleQuery& query) override {
    ScaleResult result = oracle_.StepLength(query);
    result.step_length_m *= factor_;
    return result;
  }

 private:
  OracleScaleSource oracle_;
  double factor_;
};

TEST(SequentialPipelineSynthetic, APoseBeyondWhatTheReadersAcceptIsNeverWritten) {
  constexpr int kFrames = 6;
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("urban", kFrames, dir);
  const auto source = OpenFrameSource(source_options);
  // Steps of about 5e7 m: within a few frames the camera is beyond kMaxTranslationM.
  ScaledOracle absurd(*source->ground_truth(), 5e7);
  const std::string out = dir.File("run");
  std::string message;
  try {
    RunSequentialPipeline(*source, absurd, FrameToFrame(), out);
  } catch (const Error& e) {
    message = e.what();
  }
  ASSERT_EQ(message.rfind("frame ", 0), 0u) << message;
  EXPECT_NE(message.find(": the pose would be at ("), std::string::npos) << message;
  EXPECT_NE(message.find("beyond 1e+08 m"), std::string::npos) << message;
  const size_t failed_frame = std::stoul(message.substr(6));
  EXPECT_GE(failed_frame, 1u);
  EXPECT_LT(failed_frame, static_cast<size_t>(kFrames));
  // The rows before it are intact and read back (the readers reject what was refused).
  EXPECT_EQ(ReadKittiTrajectory(out + "/poses_kitti.txt").size(), failed_frame);
  EXPECT_EQ(ReadTumTrajectory(out + "/poses_tum.txt").size(), failed_frame);
}

// A column of OUT/frames.csv, one entry per frame.
std::vector<std::string> Column(const std::string& path, const std::string& name) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  std::vector<std::string> header;
  for (std::istringstream fields(line); std::getline(fields, line, ',');) header.push_back(line);
  const size_t column = std::find(header.begin(), header.end(), name) - header.begin();
  std::vector<std::string> statuses;
  while (std::getline(file, line)) {
    std::vector<std::string> fields;
    for (std::istringstream row(line); std::getline(row, line, ',');) fields.push_back(line);
    statuses.push_back(column < fields.size() ? fields[column] : "");
  }
  return statuses;
}

TEST(SequentialPipelineSynthetic, FramesBeforeTheFirstScaleAreBackfilledOrLeftUnscaled) {
  constexpr int kFrames = 16;
  constexpr size_t kFirstScaled = 8;
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("urban", kFrames, dir);
  const Trajectory gt = *OpenFrameSource(source_options)->ground_truth();
  const auto true_step = [&](int k) {
    return (gt.world_from_cam[k].translation() - gt.world_from_cam[k - 1].translation()).norm();
  };

  // Waiting: frames 1-7 take frame 8's length scaled by their parallax.
  {
    const auto source = OpenFrameSource(source_options);
    testing::LateOracle late(gt, kFirstScaled);
    const std::string out = dir.File("backfilled");
    RunSequentialPipeline(*source, late, FrameToFrame(), out);
    const std::vector<std::string> status = Column(out + "/frames.csv", "status");
    const Trajectory est = ReadKittiTrajectory(out + "/poses_kitti.txt");
    ASSERT_EQ(status.size(), static_cast<size_t>(kFrames));
    ASSERT_EQ(est.size(), static_cast<size_t>(kFrames));
    double est_path = 0.0;
    double true_path = 0.0;
    for (int k = 1; k < kFrames; ++k) {
      EXPECT_EQ(status[k], k < static_cast<int>(kFirstScaled) ? "backfilled" : "ok") << k;
      const double step =
          (est.world_from_cam[k].translation() - est.world_from_cam[k - 1].translation()).norm();
      if (k < static_cast<int>(kFirstScaled)) {
        // The parallax ratio follows the length ratio within the change of the tracked
        // scene's depth (measured: 0.94-1.21 here, the first step off most; unit steps
        // would be 1.25 times the true ones).
        EXPECT_NEAR(step / true_step(k), 1.0, 0.22) << k;
        est_path += step;
        true_path += true_step(k);
      } else {
        EXPECT_NEAR(step, true_step(k), 1e-6) << k;
      }
    }
    EXPECT_NEAR(est_path / true_path, 1.0, 0.07);  // measured 1.054
  }
  // Not waiting long enough: the first frames are written with unit steps, flagged.
  {
    const auto source = OpenFrameSource(source_options);
    testing::LateOracle late(gt, kFirstScaled);
    PipelineOptions options = FrameToFrame();
    options.max_frames_before_first_scale = 3;
    const std::string out = dir.File("unscaled");
    RunSequentialPipeline(*source, late, options, out);
    const std::vector<std::string> status = Column(out + "/frames.csv", "status");
    const Trajectory est = ReadKittiTrajectory(out + "/poses_kitti.txt");
    ASSERT_EQ(est.size(), static_cast<size_t>(kFrames));
    for (int k = 1; k < static_cast<int>(kFirstScaled); ++k) {
      EXPECT_EQ(status[k], "unscaled") << k;
      const double step =
          (est.world_from_cam[k].translation() - est.world_from_cam[k - 1].translation()).norm();
      EXPECT_NEAR(step, 1.0, 1e-9) << k;
    }
    EXPECT_EQ(status[kFirstScaled], "ok");
  }
}

// The oracle's lengths on even positions; on odd ones the last of them again, as a source
// holds its last road model when a pair has too few road points.
class HoldingOracle : public ScaleSource {
 public:
  explicit HoldingOracle(Trajectory ground_truth) : oracle_(std::move(ground_truth)) {}
  std::string Name() const override { return "holding oracle"; }
  ScaleResult StepLength(const ScaleQuery& query) override {
    if (query.position % 2 == 0) {
      last_ = oracle_.StepLength(query);
      return last_;
    }
    ScaleResult held = last_;
    held.measured = false;
    held.status = "held: too few points";
    return held;
  }

 private:
  OracleScaleSource oracle_;
  ScaleResult last_;
};

TEST(SequentialPipelineSynthetic, AHeldLengthIsWrittenAsHeld) {
  constexpr int kFrames = 8;
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("urban", kFrames, dir);
  const auto source = OpenFrameSource(source_options);
  HoldingOracle holding(*source->ground_truth());
  const std::string out = dir.File("run");
  RunSequentialPipeline(*source, holding, FrameToFrame(), out);
  const std::vector<std::string> status = Column(out + "/frames.csv", "status");
  const std::vector<std::string> length = Column(out + "/frames.csv", "step_length_m");
  ASSERT_EQ(status.size(), static_cast<size_t>(kFrames));
  // Frame 1 waits for frame 2's first length and is backfilled.
  for (int k = 2; k < kFrames; ++k) {
    EXPECT_EQ(status[k], k % 2 == 0 ? "ok" : "held") << k;
    if (k % 2 == 1) {
      EXPECT_EQ(length[k], length[k - 1]) << k;
    }
  }
}

// The rendered labels, slowed down by a few milliseconds that depend on the frame, so that
// the segmentation threads finish their frames out of order; throws on `failing_frame`.
class UnevenSegmenter : public Segmenter {
 public:
  UnevenSegmenter(const std::string& labels, int failing_frame) : failing_frame_(failing_frame) {
    SegmentationModel model;
    model.yaml_path = labels;
    model.backend = SegmentationBackend::kLabelImages;
    model.label_images.folder = labels;
    model.label_images.ids = LabelIdSpace::kTrainIds;
    labels_ = std::make_unique<LabelImageSegmenter>(model, MaskOptions());
  }
  SegmentationResult Segment(const cv::Mat& image, const std::string& frame_name) override {
    const int frame = std::stoi(frame_name);
    if (frame == failing_frame_) throw Error("frame " + frame_name + ": made to fail");
    std::this_thread::sleep_for(std::chrono::milliseconds(frame % 3 == 0 ? 30 : 1));
    return labels_->Segment(image, frame_name);
  }
  std::string Description() const override { return "uneven labels"; }

 private:
  std::unique_ptr<LabelImageSegmenter> labels_;
  int failing_frame_;
};

// The default pipeline on a drive RenderDrive wrote, with its label masks, into dir/run: the
// estimate and the ground truth.
std::pair<Trajectory, Trajectory> RunWithLabelMasks(const FrameSourceOptions& source_options,
                                                    const testing::TempDir& dir,
                                                    const PipelineOptions& options = {}) {
  const auto source = OpenFrameSource(source_options);
  UnevenSegmenter segmenter(source_options.input + "/semantic", -1);
  RoadScaleSource road(source->camera().camera, ScaleEstimatorOptions());
  const std::string out = dir.File("run");
  RunPipeline(*source, {&segmenter}, road, options, out, RunPipelineOptions());
  return {ReadKittiTrajectory(out + "/poses_kitti.txt"), *source->ground_truth()};
}

std::string FileText(const std::string& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

TEST(SequentialPipelineSynthetic, SeveralSegmentationThreadsWriteWhatOneWrites) {
  constexpr int kFrames = 14;
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("urban", kFrames, dir);
  const std::string labels = source_options.input + "/semantic";

  PipelineOptions options;
  options.segmentation_schedule.mode = SegmentationScheduleMode::kEveryFrame;
  const auto run = [&](int threads, int failing_frame, const std::string& out) {
    const auto source = OpenFrameSource(source_options);
    std::vector<std::unique_ptr<UnevenSegmenter>> owned;
    std::vector<Segmenter*> segmenters;
    for (int i = 0; i < threads; ++i) {
      owned.push_back(std::make_unique<UnevenSegmenter>(labels, failing_frame));
      segmenters.push_back(owned.back().get());
    }
    RoadScaleSource road(source->camera().camera, ScaleEstimatorOptions());
    return RunPipeline(*source, segmenters, road, options, out);
  };
  // The keyframe back end (the default) writes the same poses with one thread as with three;
  // a failing frame still leaves every frame before it written.
  run(1, -1, dir.File("keyframe_one"));
  run(3, -1, dir.File("keyframe_three"));
  const std::string keyframe_one = FileText(dir.File("keyframe_one") + "/poses_kitti.txt");
  ASSERT_EQ(std::count(keyframe_one.begin(), keyframe_one.end(), '\n'), kFrames);
  EXPECT_EQ(FileText(dir.File("keyframe_three") + "/poses_kitti.txt"), keyframe_one);
  EXPECT_THROW(run(3, 9, dir.File("keyframe_failed")), Error);
  const std::string keyframe_failed = FileText(dir.File("keyframe_failed") + "/poses_kitti.txt");
  EXPECT_EQ(std::count(keyframe_failed.begin(), keyframe_failed.end(), '\n'), 9);

  // The frame-to-frame host writes each frame once it is processed: a failed run's rows are
  // the complete run's first rows.
  options = FrameToFrame();
  options.segmentation_schedule.mode = SegmentationScheduleMode::kEveryFrame;
  run(1, -1, dir.File("one"));
  run(3, -1, dir.File("three"));
  const std::string one = FileText(dir.File("one") + "/poses_kitti.txt");
  ASSERT_EQ(std::count(one.begin(), one.end(), '\n'), kFrames);
  EXPECT_EQ(FileText(dir.File("three") + "/poses_kitti.txt"), one);
  EXPECT_EQ(FileText(dir.File("three") + "/poses_tum.txt"),
            FileText(dir.File("one") + "/poses_tum.txt"));

  // A failing frame stops the run after the frames before it, whichever thread had them.
  EXPECT_THROW(run(3, 9, dir.File("failed")), Error);
  const std::string failed = FileText(dir.File("failed") + "/poses_kitti.txt");
  ASSERT_EQ(std::count(failed.begin(), failed.end(), '\n'), 9);
  EXPECT_EQ(failed, one.substr(0, failed.size()));
}

// Segmenting keyframes only: the network's results arrive at thread-dependent times, the
// frontend and the scale stage wait for them at fixed frames, so the threaded run (with one
// or three segmenter threads) writes what the sequential run writes, byte for byte.
TEST(SequentialPipelineSynthetic, KeyframeSegmentationWritesTheSameWithAndWithoutThreads) {
  constexpr int kFrames = 24;
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("urban", kFrames, dir);
  const std::string labels = source_options.input + "/semantic";
  for (const MappingOptions::Mode mode :
       {MappingOptions::Mode::kKeyframe, MappingOptions::Mode::kFrameToFrame}) {
    PipelineOptions options;
    options.mapping.mode = mode;
    ASSERT_EQ(options.segmentation_schedule.mode, SegmentationScheduleMode::kKeyframes);
    const auto run = [&](int threads, bool threaded, const std::string& out) {
      const auto source = OpenFrameSource(source_options);
      std::vector<std::unique_ptr<UnevenSegmenter>> owned;
      std::vector<Segmenter*> segmenters;
      for (int i = 0; i < threads; ++i) {
        owned.push_back(std::make_unique<UnevenSegmenter>(labels, -1));
        segmenters.push_back(owned.back().get());
      }
      RoadScaleSource road(source->camera().camera, ScaleEstimatorOptions());
      RunPipelineOptions run_options;
      run_options.threaded = threaded;
      return RunPipeline(*source, segmenters, road, options, out, run_options);
    };
    const std::string name = MappingModeName(mode);
    const RunSummary sequential = run(1, false, dir.File(name + "_sequential")).summary;
    run(1, true, dir.File(name + "_one"));
    run(3, true, dir.File(name + "_three"));
    // Some frames, not all, were segmented.
    EXPECT_GE(sequential.segmented_frames, 2u) << name;
    EXPECT_LT(sequential.segmented_frames, static_cast<size_t>(kFrames)) << name;
    const std::string poses = FileText(dir.File(name + "_sequential") + "/poses_kitti.txt");
    ASSERT_EQ(std::count(poses.begin(), poses.end(), '\n'), kFrames) << name;
    for (const std::string& threaded : {name + "_one", name + "_three"}) {
      EXPECT_EQ(FileText(dir.File(threaded) + "/poses_kitti.txt"), poses) << threaded;
      EXPECT_EQ(FileText(dir.File(threaded) + "/poses_tum.txt"),
                FileText(dir.File(name + "_sequential") + "/poses_tum.txt"))
          << threaded;
    }
  }
}

double PathLength(const Trajectory& trajectory) {
  double length = 0.0;
  for (size_t k = 1; k < trajectory.size(); ++k) {
    length += (trajectory.world_from_cam[k].translation() -
               trajectory.world_from_cam[k - 1].translation())
                  .norm();
  }
  return length;
}

// The keyframe back end's road alignment end to end: on a highway at 2.5 m a frame the road
// near the car leaves the view before a track on it reaches the next keyframe, so the sparse
// selection has few road points; the alignment of each keyframe pair's road pixels is what
// makes the map metric (docs/benchmark-history.md, "The road's pixels").
TEST(SequentialPipelineSynthetic, TheRoadAlignmentScalesAHighwayDrive) {
  constexpr int kFrames = 60;
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("highway", kFrames, dir);
  const std::string labels = source_options.input + "/semantic";
  std::map<bool, double> errors;
  std::map<bool, long> aligned;
  for (const bool alignment : {true, false}) {
    PipelineOptions options;
    options.mapping.road_alignment = alignment;
    const auto source = OpenFrameSource(source_options);
    UnevenSegmenter segmenter(labels, -1);
    RoadScaleSource road(source->camera().camera, ScaleEstimatorOptions());
    const std::string out = dir.File(alignment ? "on" : "off");
    RunPipeline(*source, {&segmenter}, road, options, out, RunPipelineOptions());
    errors[alignment] = std::abs(PathLength(ReadKittiTrajectory(out + "/poses_kitti.txt")) /
                                     PathLength(*source->ground_truth()) -
                                 1.0);
    const std::vector<std::string> scales = Column(out + "/frames.csv", "alignment_scale");
    aligned[alignment] = std::count_if(scales.begin(), scales.end(), [](const std::string& s) {
      return !s.empty() && std::stod(s) > 0.0;
    });
  }
  // Measured: 30 of 31 keyframe pairs aligned, lengths 0.5 % short; without the alignment 7 %
  // long.
  EXPECT_GE(aligned[true], 10);
  EXPECT_EQ(aligned[false], 0);
  EXPECT_LT(errors[true], 0.02);
  EXPECT_LT(errors[true], errors[false]);
}

// Three black frames and a burnt-out one: the tracks are lost, the frames in the gaps take the
// constant-velocity pose, and the map goes on from fresh tracks. Measured here before the
// mends: the blank frames became keyframes, the road alignment between a blank keyframe and
// the next "converged" on the guessed pose (the step after the black frames 0.31 of the
// truth), and the new part of the map, tied to the old by no landmark, drifted in the
// adjustment (steps 0.82-0.86 of the truth); now 0.94 at worst.
TEST(SequentialPipelineSynthetic, BlankFramesNeitherBreakNorStretchThePath) {
  constexpr int kFrames = 70;
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("urban", kFrames, dir);
  const std::string images = source_options.input + "/image_0/";
  const cv::Mat first = cv::imread(images + "000000.png", cv::IMREAD_GRAYSCALE);
  const auto overwrite = [&](int frame, int grey) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d.png", frame);
    ASSERT_TRUE(cv::imwrite(images + name, cv::Mat(first.size(), CV_8UC1, cv::Scalar(grey))));
  };
  for (int frame : {25, 26, 27}) overwrite(frame, 0);
  overwrite(45, 255);

  const auto [estimated, truth] = RunWithLabelMasks(source_options, dir);
  ASSERT_EQ(estimated.size(), static_cast<size_t>(kFrames));
  const std::vector<std::string> keyframe = Column(dir.File("run/frames.csv"), "keyframe");
  for (int frame : {25, 26, 27, 45}) EXPECT_EQ(keyframe[frame], "0") << frame;
  for (int k = 1; k < kFrames; ++k) {
    const auto step = [k](const Trajectory& t) {
      return (t.world_from_cam[k].translation() - t.world_from_cam[k - 1].translation()).norm();
    };
    EXPECT_NEAR(step(estimated) / step(truth), 1.0, 0.15) << k;
  }
  EXPECT_NEAR(PathLength(estimated) / PathLength(truth), 1.0, 0.03);
}

// Without segmentation the alignment samples the region ahead, and its pairs keep their vote
// against the map: on rendered highway seed 3 (300 frames rendered, the first 80 run) the
// sparse road landmarks (whatever stands below the horizon) gave the map a first scale of a
// quarter of the truth, which the pairs, each alone when it came, could not correct. Measured:
// 0.986 of the true path length; 0.215 with the region's pairs dropped as they came (checked
// with a build that dropped them), 0.212 with the region off (docs/benchmark-history.md, "Pairs of
// the region ahead keep their vote").
TEST(SequentialPipelineSynthetic, TheRoadAheadScalesAHighwayDriveWithoutSegmentation) {
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("highway", 300, dir, 3, 80);
  std::map<bool, double> ratios;
  for (const bool region : {true, false}) {
    PipelineOptions options;
    if (!region) options.mapping.road_region_max_distance = 0.0;
    const auto source = OpenFrameSource(source_options);
    RoadScaleSource road(source->camera().camera, ScaleEstimatorOptions());
    const std::string out = dir.File(region ? "region" : "no_region");
    RunSequentialPipeline(*source, road, options, out);
    ratios[region] = PathLength(ReadKittiTrajectory(out + "/poses_kitti.txt")) /
                     PathLength(*source->ground_truth());
  }
  EXPECT_NEAR(ratios[true], 1.0, 0.03);
  EXPECT_GT(std::abs(ratios[false] - 1.0), 0.1);
}

// The map's direction checked against the frame pair's (FrameLocalizerOptions::
// max_direction_change_deg) end to end: on rendered highway seed 7 a truck passing close takes
// most tracks near frame 177, one localisation goes degrees off, and without the check the
// map's direction drifts and the road alignment fails on every pair after it. Measured on the
// first 230 of its 300 frames (561 m) with label masks: 0.9934 of the true path length, the
// end 6.5 m from the truth; without the check (180 degrees) 0.9643 and 22.6 m
// (docs/benchmark-history.md, "The map's direction checked"). The run without the check is not
// asserted: where such a drive breaks depends on every digit of the run before it. The truck's
// tracks reach the map because its carried mask is moved with the road only (carry_dynamic_in_place
// off), as a network that misses a vehicle would let them in. With the default masks, which also
// keep the truck where it was, the check does not fire on this drive (the same poses with it at 180
// degrees).
TEST(SequentialPipelineSynthetic, TheDirectionCheckKeepsAHighwayPassingATruckOnItsPath) {
  testing::TempDir dir;
  const FrameSourceOptions source_options = RenderDrive("highway", 300, dir, 7, 230);
  PipelineOptions options;
  options.segmentation_schedule.carry.dynamic_in_place = false;
  const auto [estimated, truth] = RunWithLabelMasks(source_options, dir, options);
  ASSERT_EQ(estimated.size(), truth.size());
  const double length = PathLength(truth);
  EXPECT_NEAR(PathLength(estimated) / length, 1.0, 0.02);
  EXPECT_LT(
      (estimated.world_from_cam.back().translation() - truth.world_from_cam.back().translation())
          .norm(),
      0.02 * length);
}

}  // namespace
}  // namespace roadscale
