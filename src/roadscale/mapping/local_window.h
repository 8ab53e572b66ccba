#pragma once

#include <cstdint>
#include <deque>
#include <map>

#include "roadscale/mapping/keyframe.h"
#include "roadscale/mapping/landmark.h"

namespace roadscale {

// The keyframes of the sliding window, oldest first, and the landmarks they observe. Plain
// data with the bookkeeping that keeps the two consistent: every landmark is observed by at
// least two keyframes of the window.
class LocalWindow {
 public:
  std::deque<Keyframe>& keyframes() { return keyframes_; }
  const std::deque<Keyframe>& keyframes() const { return keyframes_; }
  std::map<int64_t, Landmark>& landmarks() { return landmarks_; }
  const std::map<int64_t, Landmark>& landmarks() const { return landmarks_; }

  // The keyframe of this frame, or null.
  const Keyframe* FindKeyframe(int frame_index) const;
  // Keyframes of the window that observe the track.
  int CountObservations(int64_t track_id) const;
  // Road landmarks whose anchor keyframe is in the window.
  int CountRoadLandmarks() const;
  // Keyframes with a road alignment whose earlier keyframe is still in the window: those in
  // the adjustment (RoadPairPlane::in_adjustment), or all of them.
  int CountRoadPairs() const;
  int CountRoadPairReadings() const;

  void AddKeyframe(Keyframe keyframe) { keyframes_.push_back(std::move(keyframe)); }
  // Drops the oldest keyframe, then the landmarks left with fewer than two observations and
  // the road marks whose anchor left.
  void RemoveOldestKeyframe();
  // Erases one observation and, when it leaves fewer than two, the landmark.
  void RemoveObservation(Keyframe* keyframe, int64_t track_id);
  // Erases a track everywhere: its observations in every keyframe and its landmark.
  void RemoveTrack(int64_t track_id);
  // Multiplies every keyframe position and landmark by `factor` about the oldest keyframe's
  // centre (a change of the map's scale that keeps the oldest keyframe where it is).
  void Rescale(double factor);
  // A pose outside the window moved as Rescale moves the window's.
  Rigid3d RescaledPose(const Rigid3d& cam_from_world, double factor) const;

 private:
  int CountRoadPairsIf(bool in_adjustment_only) const;
  // Erases the landmarks observed by fewer than two keyframes.
  void RemoveWeakLandmarks();

  std::deque<Keyframe> keyframes_;
  std::map<int64_t, Landmark> landmarks_;
};

}  // namespace roadscale
