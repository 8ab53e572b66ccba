#include "roadscale/testing/mapping_test_scene.h"

#include <cmath>

#include "roadscale/util/random.h"

namespace roadscale::testing {

MappingTestScene MappingTestScene::Street(int frames, double step_m, double yaw_deg_per_frame,
                                          uint32_t seed) {
  MappingTestScene scene;
  Rng rng(seed);
  const double length = frames * step_m + 40.0;
  // Road: a textured lane and its neighbours.
  // One draw a statement here and below: the order of a call's arguments is the compiler's,
  // and the scene must be the same with every compiler.
  for (int i = 0; i < static_cast<int>(length * 12); ++i) {
    const double z = rng.Uniform(2.0, 2.0 + length);
    const double x = rng.Uniform(-5.0, 5.0);
    scene.points.emplace_back(x, scene.camera_height, z);
    scene.is_road.push_back(true);
  }
  // Facades on both sides, from the road up to 8 m above it.
  for (int i = 0; i < static_cast<int>(length * 12); ++i) {
    const double side = rng.Bernoulli(0.5) ? -1.0 : 1.0;
    const double z = rng.Uniform(2.0, 2.0 + length);
    const double y = scene.camera_height - rng.Uniform(0.0, 8.0);
    const double x = side * rng.Uniform(7.0, 8.0);
    scene.points.emplace_back(x, y, z);
    scene.is_road.push_back(false);
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double yaw = 0.0;
  for (int f = 0; f < frames; ++f) {
    const Eigen::Matrix3d world_from_cam_rotation =
        Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
    scene.cam_from_world.push_back(MakeRigid3d(world_from_cam_rotation, centre).inverse());
    centre += world_from_cam_rotation * Eigen::Vector3d(0.0, 0.0, step_m);
    yaw += yaw_deg_per_frame * M_PI / 180.0;
  }
  return scene;
}

std::vector<TrackObservation> MappingTestScene::Observe(int frame, double noise_px,
                                                        uint32_t seed) const {
  Rng rng(seed + 7919u * static_cast<uint32_t>(frame));
  std::vector<TrackObservation> observations;
  for (size_t id = 0; id < points.size(); ++id) {
    const Eigen::Vector3d point_cam = cam_from_world[frame] * points[id];
    if (point_cam.z() < 1.0 || point_cam.z() > 60.0) continue;
    Eigen::Vector2d pixel = camera.Project(point_cam);
    if (!camera.IsInside(pixel)) continue;
    if (noise_px > 0.0) {
      const double dy = noise_px * rng.Normal();
      const double dx = noise_px * rng.Normal();
      pixel += Eigen::Vector2d(dx, dy);
    }
    observations.push_back({static_cast<int64_t>(id), pixel});
  }
  return observations;
}

FrontendFrame MappingTestScene::Frontend(int frame, double noise_px, uint32_t seed) const {
  FrontendFrame result;
  result.frame_index = frame;
  result.observations = Observe(frame, noise_px, seed);
  if (frame == 0) {
    result.motion.status = MotionStatus::kFirstFrame;
    return result;
  }
  const Rigid3d cur_from_prev = cam_from_world[frame] * cam_from_world[frame - 1].inverse();
  const double length = cur_from_prev.translation().norm();
  result.motion.rotation = cur_from_prev.linear();
  if (length < 1e-9) {
    result.motion.status = MotionStatus::kStationary;
    result.motion.rotation = Eigen::Matrix3d::Identity();
    return result;
  }
  result.motion.status = MotionStatus::kOk;
  result.motion.direction = cur_from_prev.translation() / length;
  return result;
}

LocalWindow ExactWindow(const MappingTestScene& scene, int keyframes, int spacing) {
  LocalWindow window;
  for (int k = 0; k < keyframes; ++k) {
    Keyframe keyframe;
    keyframe.frame_index = k * spacing;
    keyframe.cam_from_world = scene.cam_from_world[keyframe.frame_index];
    for (const TrackObservation& o : scene.Observe(keyframe.frame_index, 0.0, 0)) {
      keyframe.observations[o.track_id] = o.pixel;
    }
    window.AddKeyframe(std::move(keyframe));
  }
  for (size_t id = 0; id < scene.points.size(); ++id) {
    const int64_t track = static_cast<int64_t>(id);
    if (window.CountObservations(track) < 2) continue;
    Landmark landmark;
    landmark.position = scene.points[id];
    if (scene.is_road[id]) {
      for (const Keyframe& keyframe : window.keyframes()) {
        if (keyframe.observations.count(track) == 0) continue;
        landmark.is_road = true;
        landmark.road_anchor_frame = keyframe.frame_index;
        // The road is the plane y = h0 of the world; in the keyframe's frame its normal is
        // the world's down axis rotated into the camera.
        landmark.road_normal_in_anchor =
            keyframe.cam_from_world.linear() * Eigen::Vector3d::UnitY();
        break;
      }
    }
    window.landmarks().emplace(track, landmark);
  }
  return window;
}

}  // namespace roadscale::testing
