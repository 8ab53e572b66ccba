#include "roadscale/mapping/local_window.h"

namespace roadscale {

const Keyframe* LocalWindow::FindKeyframe(int frame_index) const {
  for (const Keyframe& keyframe : keyframes_) {
    if (keyframe.frame_index == frame_index) return &keyframe;
  }
  return nullptr;
}

int LocalWindow::CountObservations(int64_t track_id) const {
  int count = 0;
  for (const Keyframe& keyframe : keyframes_) count += keyframe.observations.count(track_id);
  return count;
}

int LocalWindow::CountRoadLandmarks() const {
  int count = 0;
  for (const auto& [id, landmark] : landmarks_) {
    if (landmark.is_road && FindKeyframe(landmark.road_anchor_frame) != nullptr) ++count;
  }
  return count;
}

int LocalWindow::CountRoadPairs() const { return CountRoadPairsIf(true); }

int LocalWindow::CountRoadPairReadings() const { return CountRoadPairsIf(false); }

int LocalWindow::CountRoadPairsIf(bool in_adjustment_only) const {
  int count = 0;
  for (const Keyframe& keyframe : keyframes_) {
    if (keyframe.road_pair && (!in_adjustment_only || keyframe.road_pair->in_adjustment) &&
        FindKeyframe(keyframe.road_pair->anchor_frame) != nullptr) {
      ++count;
    }
  }
  return count;
}

void LocalWindow::RemoveOldestKeyframe() {
  if (keyframes_.empty()) return;
  const int oldest = keyframes_.front().frame_index;
  keyframes_.pop_front();
  for (auto& [id, landmark] : landmarks_) {
    if (landmark.is_road && landmark.road_anchor_frame == oldest) landmark.is_road = false;
  }
  RemoveWeakLandmarks();
}

void LocalWindow::RemoveObservation(Keyframe* keyframe, int64_t track_id) {
  keyframe->observations.erase(track_id);
  const auto landmark = landmarks_.find(track_id);
  if (landmark != landmarks_.end() && CountObservations(track_id) < 2) landmarks_.erase(landmark);
}

void LocalWindow::RemoveTrack(int64_t track_id) {
  for (Keyframe& keyframe : keyframes_) keyframe.observations.erase(track_id);
  landmarks_.erase(track_id);
}

void LocalWindow::RemoveWeakLandmarks() {
  for (auto it = landmarks_.begin(); it != landmarks_.end();) {
    it = CountObservations(it->first) < 2 ? landmarks_.erase(it) : std::next(it);
  }
}

void LocalWindow::Rescale(double factor) {
  if (keyframes_.empty()) return;
  const Eigen::Vector3d origin = keyframes_.front().cam_from_world.inverse().translation();
  for (Keyframe& keyframe : keyframes_) {
    keyframe.cam_from_world = RescaledPose(keyframe.cam_from_world, factor);
    keyframe.baseline_at_creation *= factor;
  }
  for (auto& [id, landmark] : landmarks_) {
    landmark.position = origin + factor * (landmark.position - origin);
  }
}

Rigid3d LocalWindow::RescaledPose(const Rigid3d& cam_from_world, double factor) const {
  if (keyframes_.empty()) return cam_from_world;
  // The oldest keyframe's centre is the fixed point, so it may be read before or after Rescale.
  const Eigen::Vector3d origin = keyframes_.front().cam_from_world.inverse().translation();
  Rigid3d world_from_cam = cam_from_world.inverse();
  world_from_cam.translation() = origin + factor * (world_from_cam.translation() - origin);
  return world_from_cam.inverse();
}

}  // namespace roadscale
