#pragma once

#include <cstddef>
#include <string>

#include "roadscale/io/frame_source.h"
#include "roadscale/pipeline/bounded_queue.h"

namespace roadscale {

// A FrameSource whose frames are handed in one by one by another thread (Odometry::Track)
// instead of read from files: Next() waits for the next pushed frame, and returns false once
// the producer has closed the source and every frame is taken.
class PushedFrames : public FrameSource {
 public:
  // `capacity`: frames that may wait before Push blocks (at least 1).
  PushedFrames(const CameraSetup& camera, size_t capacity);

  const CameraSetup& camera() const override { return camera_; }
  // Unknown ahead: frames arrive as they are pushed.
  size_t size() const override { return 0; }
  bool Next(Frame* frame) override;
  std::string Describe() const override { return "frames handed in by the program"; }

  // Waits for room, then queues `frame`. Returns false (the frame dropped) once the consumer
  // has stopped (Cancel).
  bool Push(Frame frame) { return queue_.Push(std::move(frame)); }
  // No more frames: Next() delivers the queued ones, then returns false.
  void Close() { queue_.Close(); }
  // The consumer has stopped: Push returns false at once, queued frames are dropped.
  void Cancel() { queue_.Cancel(); }

 private:
  CameraSetup camera_;
  BoundedQueue<Frame> queue_;
};

}  // namespace roadscale
