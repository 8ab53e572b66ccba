// `roadscale rescale`'s claim, end to end through the library: a ground truth whose scale
// was destroyed by a seeded, slowly drifting factor (as a monocular VO's) gets its metric
// scale back from the road plane, on a rendered street and on the shared KITTI 00 frames
// (keyframes only). Rendering and KLT over hundreds of frames make it slow (label `slow`).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roadscale/eval/kitti_odometry_metric.h"
#include "roadscale/eval/scale_drift.h"
#include "roadscale/eval/trajectory_errors.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/io/trajectory_io.h"
#include "roadscale/rescale/trajectory_rescaler.h"
#include "roadscale/segmentation/label_image_segmenter.h"
#include "roadscale/synth/scene_writer.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/temp_dir.h"

namespace roadscale {
namespace {

struct Rescaled {
  std::vector<Rigid3d> gt;        // the ground truth at the poses' frames
  std::vector<Rigid3d> external;  // the destroyed input
  std::vector<Rigid3d> metric;    // the output
  int ok = 0;
  int aligned = 0;  // steps whose road alignment converged
};

// Destroys the scale of `sequence_dir`'s ground truth, keeps every `every`-th pose, and
// rescales it; `labels_dir` (Cityscapes train ids) gives the road mask when not empty.
Rescaled DestroyAndRescale(const std::string& sequence_dir, size_t every,
                           const std::string& labels_dir) {
  FrameSourceOptions source_options;
  source_options.input = sequence_dir;
  source_options.type = FrameSourceType::kKitti;
  const KittiSequence source(source_options);
  EXPECT_NE(source.ground_truth(), nullptr);
  const Trajectory& gt = *source.ground_truth();
  const Trajectory external = KeepEveryNthPose(DistortTrajectoryScale(gt, {}), every);
  const std::vector<size_t> pose_frames =
      AssociatePosesWithFrames(external, "external", source.timestamps());

  std::unique_ptr<Segmenter> segmenter;
  if (!labels_dir.empty()) {
    SegmentationModel model;
    model.backend = SegmentationBackend::kLabelImages;
    model.label_images.folder = labels_dir;
    segmenter = std::make_unique<LabelImageSegmenter>(model, MaskOptions());
  }
  TrajectoryRescalerOptions options;
  options.scale.camera_height = source.camera().h0;
  TrajectoryRescaler rescaler(source.camera().camera, external, pose_frames, options);
  Rescaled result;
  RunTrajectoryRescaler(source, segmenter.get(), rescaler, [&](const RescaledPose& pose) {
    result.metric.push_back(pose.world_from_cam);
    if (pose.status == RescaleStatus::kOk) ++result.ok;
    if (std::isfinite(pose.alignment_ratio)) ++result.aligned;
  });
  for (size_t k = 0; k < pose_frames.size(); ++k) {
    result.gt.push_back(gt.world_from_cam[pose_frames[k]]);
    result.external.push_back(external.world_from_cam[k]);
  }
  return result;
}

class RescaleSyntheticTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    synth::SyntheticScene scene(synth::PresetSceneOptions("urban"), 80);
    synth::SceneWriterOptions writer;
    writer.out_dir = dir_->path().string();
    synth::WriteSyntheticSequence(scene, writer);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::string Sequence() { return (dir_->path() / "sequences" / "00").string(); }

  static testing::TempDir* dir_;
};
testing::TempDir* RescaleSyntheticTest::dir_ = nullptr;

TEST_F(RescaleSyntheticTest, RecoversTheScaleOfAnUrbanStreetWithItsRoadLabels) {
  const Rescaled run = DestroyAndRescale(Sequence(), 1, Sequence() + "/semantic");
  ASSERT_EQ(run.metric.size(), 80u);
  const TrajectoryErrors destroyed = ComputeTrajectoryErrors(run.gt, run.external);
  const TrajectoryErrors rescaled = ComputeTrajectoryErrors(run.gt, run.metric);
  // The input is about 0.33 times as long as the truth.
  EXPECT_LT(*destroyed.length_ratio, 0.4);
  // Measured (2026-12-01, the default pixel-space plane refit): length ratio 1.010, ATE se3
  // 0.25 m, 78 of 79 steps scaled from their own road plane (the paper's plane: 1.023,
  // 0.46 m). The scenes' rendering still changes, so the
  // tolerance leaves room beyond the measured error.
  EXPECT_NEAR(*rescaled.length_ratio, 1.0, 0.05);
  EXPECT_LT(rescaled.ate_se3_m, 1.0);
  EXPECT_GE(run.ok, 70);
  // The road alignment converged on most steps (it needs the road masks).
  EXPECT_GE(run.aligned, 60);
}

TEST_F(RescaleSyntheticTest, RecoversTheScaleWithoutSegmentation) {
  const Rescaled run = DestroyAndRescale(Sequence(), 1, "");
  ASSERT_EQ(run.metric.size(), 80u);
  const TrajectoryErrors rescaled = ComputeTrajectoryErrors(run.gt, run.metric);
  // Measured: 1.015, ATE se3 0.30 m, every step scaled (the paper's plane: 0.993, 0.19 m).
  EXPECT_NEAR(*rescaled.length_ratio, 1.0, 0.05);
  EXPECT_GE(run.ok, 70);
  EXPECT_EQ(run.aligned, 0);  // no road mask, no alignment
}

TEST(RescaleKitti, RecoversTheScaleOfKeyframesOnTheSharedKitti00Frames) {
  ROADSCALE_REQUIRE_SHARED("kitti/sequences/00/image_0/000199.png");
  ROADSCALE_REQUIRE_SHARED("kitti/poses/00.txt");
  const Rescaled run = DestroyAndRescale(testing::SharedPath("kitti/sequences/00").string(), 3, "");
  ASSERT_EQ(run.metric.size(), 67u);  // frames 0, 3, ..., 198
  const TrajectoryErrors destroyed = ComputeTrajectoryErrors(run.gt, run.external);
  const TrajectoryErrors rescaled = ComputeTrajectoryErrors(run.gt, run.metric);
  EXPECT_LT(*destroyed.length_ratio, 0.4);
  // Measured without segmentation: 0.991 (ATE se3 0.41 m over 144 m), 64 of 66 steps scaled
  // (the paper's plane: 0.965, 0.99 m).
  EXPECT_NEAR(*rescaled.length_ratio, 1.0, 0.05);
  EXPECT_LT(rescaled.ate_se3_m, 2.0);
  EXPECT_GE(run.ok, 60);
}

// The floor of a trajectory: its own rotations and directions with each step's true length,
// the best any per-step scale can do (a step the input does not move stays 0).
std::vector<Rigid3d> FloorOf(const std::vector<Rigid3d>& input, const std::vector<Rigid3d>& gt) {
  std::vector<Rigid3d> floor = {input.front()};
  Eigen::Vector3d position = input.front().translation();
  for (size_t i = 1; i < input.size(); ++i) {
    const Eigen::Vector3d step = input[i].translation() - input[i - 1].translation();
    if (step.norm() > 0.0) {
      position += step.normalized() * (gt[i].translation() - gt[i - 1].translation()).norm();
    }
    floor.push_back(MakeRigid3d(input[i].linear(), position));
  }
  return floor;
}

struct PeerCase {
  const char* trajectory;  // in ../shared/peer_trajectories/
  const char* sequence;    // in ../shared/kitti/sequences/
  // Bounds on |length ratio - the floor's| and on ATE se3 over the floor's. Measured on this
  // path (no segmentation, 2026-12-08, with the steps without a road plane measured over a
  // span of poses): Wang 00 0.013 / 3.5, LibVISO2-M 00 0.0038 / 1.35, Wang 07 0.0125 / 8.8,
  // LibVISO2-M 07 0.025 / 1.64 (before the spans: 0.014 / 3.6, 0.0075 / 1.46, 0.023 / 6.6,
  // 0.0030 / 1.47; LibVISO2-M's floor on 07 is itself 1.3 % short, since it repeats a pose
  // where it fails, and the spans end 1.2 % long where the held steps ended 1.0 % short).
  // Each bound is that with a margin against regressions, not the target
  // (docs/benchmark-history.md, "Held steps measured over a span of poses").
  double max_ratio_gap;
  double max_ate_over_floor;
};

class RescalePeers : public ::testing::TestWithParam<PeerCase> {};

// Two public monocular VOs' real trajectories on the shared frames (Wang et al. 2018's
// scale-recovery VO and LibVISO2-M, which repeats a pose where it fails), rescaled as
// `roadscale rescale --no-segmentation` does, against their floors.
TEST_P(RescalePeers, ComesNearTheFloorOfItsOwnDirections) {
  const PeerCase& peer = GetParam();
  const std::string input_path = std::string("peer_trajectories/") + peer.trajectory + ".txt";
  ROADSCALE_REQUIRE_SHARED(input_path);
  ROADSCALE_REQUIRE_SHARED(std::string("kitti/sequences/") + peer.sequence + "/image_0/000159.png");
  FrameSourceOptions source_options;
  source_options.input =
      testing::SharedPath(std::string("kitti/sequences/") + peer.sequence).string();
  source_options.type = FrameSourceType::kKitti;
  const KittiSequence source(source_options);
  ASSERT_NE(source.ground_truth(), nullptr);
  const Trajectory input = ReadKittiTrajectory(testing::SharedPath(input_path).string());
  const std::vector<size_t> pose_frames =
      AssociatePosesWithFrames(input, "input", source.timestamps());
  ASSERT_EQ(pose_frames.size(), source.ground_truth()->size());

  TrajectoryRescalerOptions options;
  options.scale.camera_height = source.camera().h0;
  TrajectoryRescaler rescaler(source.camera().camera, input, pose_frames, options);
  std::vector<Rigid3d> metric;
  RunTrajectoryRescaler(source, nullptr, rescaler,
                        [&](const RescaledPose& pose) { metric.push_back(pose.world_from_cam); });
  const std::vector<Rigid3d>& gt = source.ground_truth()->world_from_cam;
  ASSERT_EQ(metric.size(), gt.size());
  const std::vector<Rigid3d> floor = FloorOf(input.world_from_cam, gt);
  const TrajectoryErrors floor_errors = ComputeTrajectoryErrors(gt, floor);
  const TrajectoryErrors rescaled = ComputeTrajectoryErrors(gt, metric);
  EXPECT_LT(std::abs(*rescaled.length_ratio - *floor_errors.length_ratio), peer.max_ratio_gap)
      << "rescaled " << *rescaled.length_ratio << ", floor " << *floor_errors.length_ratio;
  EXPECT_LT(rescaled.ate_se3_m, peer.max_ate_over_floor * floor_errors.ate_se3_m)
      << "rescaled " << rescaled.ate_se3_m << " m, floor " << floor_errors.ate_se3_m << " m";
  const KittiOdometryResult kitti = EvaluateKittiOdometry(gt, metric);
  const KittiOdometryResult kitti_floor = EvaluateKittiOdometry(gt, floor);
  if (kitti.t_err && kitti_floor.t_err) {
    RecordProperty("t_err_over_floor", std::to_string(*kitti.t_err / *kitti_floor.t_err));
  }
}

INSTANTIATE_TEST_SUITE_P(SharedKitti, RescalePeers,
                         ::testing::Values(PeerCase{"wang2018_00_0-199", "00", 0.02, 5.0},
                                           PeerCase{"libviso2m_00_0-199", "00", 0.015, 2.0},
                                           PeerCase{"wang2018_07_0-159", "07", 0.02, 11.0},
                                           PeerCase{"libviso2m_07_0-159", "07", 0.035, 2.0}),
                         [](const ::testing::TestParamInfo<PeerCase>& info) {
                           std::string name = info.param.trajectory;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace roadscale
