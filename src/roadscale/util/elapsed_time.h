#pragma once

#include <chrono>

namespace roadscale {

// Wall time since `start` in milliseconds, for the per-stage timings the outputs report.
inline double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace roadscale
