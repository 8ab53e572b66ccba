#pragma once

#include <atomic>

namespace roadscale::cli {

// While an InterruptScope lives, SIGINT (Ctrl-C) and SIGTERM (what `kill`, `timeout` and
// container stops send) set interrupted() instead of ending the process, so that a run stops
// after the work in flight with its files complete. A second signal ends the process as
// usual (the handler puts the default action back). The previous handlers return with the
// scope's end.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  // The flag the pipelines poll.
  static const std::atomic<bool>& interrupted();
};

}  // namespace roadscale::cli
