#include "roadscale/synth/synthetic_scene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <thread>

#include "roadscale/geometry/angles.h"
#include "roadscale/synth/road_generator.h"
#include "roadscale/util/error.h"

namespace roadscale::synth {
namespace {

constexpr double kNearDistance = 0.1;

}  // namespace

SyntheticScene::SyntheticScene(const SceneOptions& options, int frames)
    : options_(options), frames_(frames) {
  options_.Check();
  CheckOption(frames >= 1, "frames", "must be at least 1");
  Rng root(options.seed);
  Rng road_rng = root.Fork(1);
  Rng motion_rng = root.Fork(2);
  Rng world_rng = root.Fork(3);
  Rng traffic_rng = root.Fork(4);
  Rng misc_rng = root.Fork(5);

  const double duration = (frames - 1) / options_.image.frame_rate;
  motion_ = std::make_unique<VehicleMotion>(options_.vehicle, duration, motion_rng);
  // Road enough for the last frame's view, and for the lead car ahead of it.
  const double u_end = motion_->PositionAt(duration + 2.0) + options_.image.far_distance +
                       options_.traffic.lead_gap_max + 40.0;
  std::vector<RoadPiece> pieces = options_.road.pieces;
  if (pieces.empty()) {
    pieces = GenerateRoadPieces(options_.road, options_.vehicle.start_position, u_end, road_rng);
  } else {
    // An explicit road too short for the drive goes on straight.
    double length = 0.0;
    for (const RoadPiece& piece : pieces) length += piece.length;
    if (length < u_end) {
      RoadPiece rest = pieces.back();
      rest.curvature = 0.0;
      rest.length = u_end - length;
      pieces.push_back(rest);
    }
  }
  layout_ = MakeLateralLayout(options_.road);
  line_ = std::make_unique<CentreLine>(
      pieces, RoadCrown{options_.road.crown_slope, layout_.right_edge, layout_.left_edge});
  const double u_begin = -30.0;
  index_ = std::make_unique<RoadIndex>(*line_, u_begin - 60.0, u_end + 60.0);

  const double elevation = options_.image.sun_elevation_deg * kRadiansPerDegree;
  const double azimuth = options_.image.sun_azimuth_deg * kRadiansPerDegree;
  sun_ = Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                         std::cos(elevation) * std::sin(azimuth), std::sin(elevation));

  world_ = BuildStaticWorld(options_, *line_, layout_, *index_, sun_, u_begin, u_end, world_rng);
  traffic_ = std::make_unique<Traffic>(options_, *line_, layout_, *motion_, duration, u_begin,
                                       u_end, sun_, traffic_rng);
  textures_.options = options_.texture;
  textures_.markings = layout_.markings;
  textures_.seed = static_cast<uint32_t>(misc_rng.NextU64());
  noise_seed_ = static_cast<uint32_t>(misc_rng.NextU64());
  sky_seed_ = static_cast<uint32_t>(misc_rng.NextU64());
  exposure_phase_ = misc_rng.Uniform(0.0, 2.0 * M_PI);
  world_from_scene_ = SceneFromCam(0).inverse();
  rasterizer_ = std::make_unique<Rasterizer>(options_.image.camera, kNearDistance,
                                             options_.image.far_distance);
}

VehicleState SyntheticScene::EgoState(int index) const { return motion_->StateAt(Time(index)); }

Rigid3d SyntheticScene::SceneFromCam(int index) const {
  return VehicleMotion::WorldFromCam(*line_, EgoState(index), options_.vehicle.h0,
                                     options_.vehicle.camera_ahead);
}

Rigid3d SyntheticScene::WorldFromCam(int index) const {
  // Frame 0 is the world by definition; the product would leave rounding noise.
  if (index == 0) return Rigid3d::Identity();
  return world_from_scene_ * SceneFromCam(index);
}

RoadPlane SyntheticScene::TrueRoadPlane(int index) const {
  const VehicleState state = EgoState(index);
  const RoadFrame frame = line_->FrameAt(state.position);
  const Rigid3d cam_from_scene = SceneFromCam(index).inverse();
  RoadPlane plane;
  plane.normal = cam_from_scene.linear() * -frame.normal;
  plane.height = plane.normal.dot(cam_from_scene * frame.point);
  return plane;
}

SynthFrame SyntheticScene::Render(int index, bool colour) {
  if (index < 0 || index >= frames_) throw Error("frame index out of range");
  SynthFrame frame;
  frame.index = index;
  frame.time = Time(index);
  frame.state = EgoState(index);
  const Rigid3d scene_from_cam = SceneFromCam(index);
  const Rigid3d cam_from_scene = scene_from_cam.inverse();
  frame.world_from_cam = WorldFromCam(index);
  frame.road_plane = TrueRoadPlane(index);

  const ImageOptions& image = options_.image;
  const PinholeCamera& camera = image.camera;
  Rasterizer& rasterizer = *rasterizer_;
  rasterizer.BeginFrame(cam_from_scene.linear() * sun_, image.ambient);

  // Chunks in view: bounding sphere against the near/far planes and the side planes.
  const double fx = camera.fx, fy = camera.fy, cx = camera.cx, cy = camera.cy;
  const Eigen::Vector3d sides[4] = {{-fx, 0.0, -(cx + 0.5)},
                                    {fx, 0.0, -(camera.width - 0.5 - cx)},
                                    {0.0, -fy, -(cy + 0.5)},
                                    {0.0, fy, -(camera.height - 0.5 - cy)}};
  for (const Chunk& chunk : world_.chunks) {
    if (chunk.mesh.empty()) continue;
    const Eigen::Vector3d c = cam_from_scene * chunk.centre;
    if (c.z() + chunk.radius < kNearDistance || c.z() - chunk.radius > image.far_distance) {
      continue;
    }
    bool outside = false;
    for (const Eigen::Vector3d& plane : sides) {
      if (plane.dot(c) > chunk.radius * plane.norm()) {
        outside = true;
        break;
      }
    }
    if (!outside) rasterizer.AddMesh(chunk.mesh, cam_from_scene);
  }

  const double u = frame.state.position;
  std::vector<ActorPose> actors;
  std::vector<Mesh> scratch;
  std::vector<GroundShadow> shadows;
  traffic_->Collect(frame.time, u - 40.0, u + image.far_distance, &actors, &scratch, &shadows);
  for (const ActorPose& actor : actors) {
    rasterizer.AddMesh(*actor.mesh, cam_from_scene * actor.world_from_mesh, actor.moving);
  }
  // Ground shadows near the road in view: the parked cars' and this frame's moving cars'.
  const auto first = std::lower_bound(world_.shadows.begin(), world_.shadows.end(), u - 40.0,
                                      [](const GroundShadow& s, double v) { return s.u_min < v; });
  for (auto it = first; it != world_.shadows.end() && it->u_min < u + image.far_distance; ++it) {
    shadows.push_back(*it);
  }
  std::stable_sort(shadows.begin(), shadows.end(),
                   [](const GroundShadow& a, const GroundShadow& b) { return a.u_min < b.u_min; });

  frame.images.grey.create(camera.height, camera.width, CV_8UC1);
  frame.images.labels.create(camera.height, camera.width, CV_8UC1);
  frame.images.depth.create(camera.height, camera.width, CV_16UC1);
  frame.images.moving.create(camera.height, camera.width, CV_8UC1);
  if (colour) frame.images.colour.create(camera.height, camera.width, CV_8UC3);

  ShadingInputs inputs;
  inputs.rasterizer = &rasterizer;
  inputs.textures = &textures_;
  inputs.world_from_cam_rotation = scene_from_cam.linear();
  inputs.shadows = &shadows;
  inputs.tree_shadows = &world_.tree_shadows;
  inputs.ambient = image.ambient;
  inputs.haze_distance = image.haze_distance;
  inputs.far_distance = image.far_distance;
  inputs.exposure =
      1.0 + image.exposure_variation *
                std::sin(2.0 * M_PI * frame.time / image.exposure_period_s + exposure_phase_);
  inputs.noise_sigma = image.noise_sigma;
  inputs.noise_seed = Hash32(noise_seed_ + static_cast<uint32_t>(index) * 0x9e3779b9U);
  inputs.sky_seed = sky_seed_;

  // Rasterize one band of rows per thread; then shade: the road fills the lower half and
  // costs most, so threads take turns at bands of 8 rows to share it evenly.
  const int threads = std::min(image.threads, camera.height);
  auto run = [threads](const std::function<void(int)>& work) {
    std::vector<std::thread> workers;
    for (int k = 1; k < threads; ++k) workers.emplace_back(work, k);
    work(0);
    for (std::thread& worker : workers) worker.join();
  };
  run([&](int k) {
    rasterizer.Rasterize(camera.height * k / threads, camera.height * (k + 1) / threads);
  });
  constexpr int kShadeBand = 8;
  run([&](int k) {
    for (int row = k * kShadeBand; row < camera.height; row += threads * kShadeBand) {
      ShadeRows(inputs, row, std::min(camera.height, row + kShadeBand), &frame.images);
    }
  });
  return frame;
}

}  // namespace roadscale::synth
