#include "roadscale/odometry/pushed_frames.h"

#include <optional>
#include <utility>

namespace roadscale {

PushedFrames::PushedFrames(const CameraSetup& camera, size_t capacity)
    : camera_(camera), queue_(capacity) {}

bool PushedFrames::Next(Frame* frame) {
  std::optional<Frame> next = queue_.Pop();
  if (!next) return false;
  *frame = std::move(*next);
  return true;
}

}  // namespace roadscale
