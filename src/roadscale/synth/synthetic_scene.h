#pragma once

#include <memory>
#include <vector>

#include "roadscale/geometry/rigid3.h"
#include "roadscale/synth/centre_line.h"
#include "roadscale/synth/frame_shader.h"
#include "roadscale/synth/procedural_texture.h"
#include "roadscale/synth/rasterizer.h"
#include "roadscale/synth/road_layout.h"
#include "roadscale/synth/scene_options.h"
#include "roadscale/synth/static_world.h"
#include "roadscale/synth/traffic.h"
#include "roadscale/synth/vehicle_motion.h"

#include <Eigen/Core>

namespace roadscale::synth {

// The true road plane in the camera frame: n . X = height for road points near the car,
// n the unit road normal pointing down (along the camera's y axis), height > 0.
struct RoadPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double height = 0.0;
};

// One rendered frame with its ground truth.
struct SynthFrame {
  int index = 0;
  double time = 0.0;  // seconds
  FrameImages images;
  Rigid3d world_from_cam = Rigid3d::Identity();  // world = camera of frame 0
  RoadPlane road_plane;
  VehicleState state;
};

// A synthetic driving sequence: road, roadside, traffic and the ego vehicle's motion are
// built from the options and the seed when the scene is constructed; Render() draws one
// frame. The same options and seed give the same frames, bit for bit, whatever the number
// of rendering threads.
class SyntheticScene {
 public:
  // Throws Error when the options fail Check() or frames < 1.
  SyntheticScene(const SceneOptions& options, int frames);

  int frames() const { return frames_; }
  const SceneOptions& options() const { return options_; }
  double Time(int index) const { return index / options_.image.frame_rate; }
  VehicleState EgoState(int index) const;

  // Poses of the camera: in the scene's own frame (z up, the road starts at the origin)
  // and in the output world (camera of frame 0, KITTI's convention).
  Rigid3d SceneFromCam(int index) const;
  Rigid3d WorldFromCam(int index) const;
  const Rigid3d& world_from_scene() const { return world_from_scene_; }
  RoadPlane TrueRoadPlane(int index) const;

  const CentreLine& centre_line() const { return *line_; }
  const VehicleMotion& motion() const { return *motion_; }
  const LateralLayout& layout() const { return layout_; }

  // Renders frame `index` (0 <= index < frames()); `colour` adds the BGR image.
  SynthFrame Render(int index, bool colour);

 private:
  SceneOptions options_;
  int frames_ = 0;
  std::unique_ptr<VehicleMotion> motion_;
  std::unique_ptr<CentreLine> line_;
  LateralLayout layout_;
  std::unique_ptr<RoadIndex> index_;
  Eigen::Vector3d sun_;
  StaticWorld world_;
  std::unique_ptr<Traffic> traffic_;
  TextureContext textures_;
  Rigid3d world_from_scene_ = Rigid3d::Identity();
  std::unique_ptr<Rasterizer> rasterizer_;
  uint32_t noise_seed_ = 0, sky_seed_ = 0;
  double exposure_phase_ = 0.0;
};

}  // namespace roadscale::synth
