#include "roadscale/scale/scale_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "roadscale/util/error.h"

namespace roadscale {

void ScaleFilterOptions::Check() const {
  CheckOption(window >= 1, "filter.window", "must be at least 1");
  CheckOption(std::isfinite(gaussian_sigma) && gaussian_sigma >= 0.0, "filter.gaussian_sigma",
              "must be 0 (off) or positive");
  CheckOption(std::isfinite(max_change_per_frame) && max_change_per_frame >= 0.0,
              "filter.max_change_per_frame", "must be 0 (off) or positive");
}

ScaleFilter::ScaleFilter(const ScaleFilterOptions& options)
    : options_(options), current_(std::numeric_limits<double>::quiet_NaN()) {
  options_.Check();
}

double ScaleFilter::FilterWindow(const std::vector<double>& window, double gaussian_sigma) {
  if (window.empty()) return std::numeric_limits<double>::quiet_NaN();
  const int count = static_cast<int>(window.size());
  std::vector<double> smoothed(window);
  if (gaussian_sigma > 0.0) {
    for (int i = 0; i < count; ++i) {
      double weighted_sum = 0.0;
      double weight_sum = 0.0;
      for (int j = 0; j < count; ++j) {
        const double offset = i - j;
        const double weight = std::exp(-offset * offset / (2.0 * gaussian_sigma * gaussian_sigma));
        weighted_sum += weight * window[j];
        weight_sum += weight;
      }
      smoothed[i] = weighted_sum / weight_sum;
    }
  }
  const size_t middle = smoothed.size() / 2;
  std::nth_element(smoothed.begin(), smoothed.begin() + middle, smoothed.end());
  const double upper = smoothed[middle];
  if (smoothed.size() % 2 == 1) return upper;
  const double lower = *std::max_element(smoothed.begin(), smoothed.begin() + middle);
  return 0.5 * (lower + upper);
}

double ScaleFilter::Add(double raw_scale) {
  if (!std::isfinite(raw_scale) || raw_scale <= 0.0) return current_;
  window_.push_back(raw_scale);
  while (static_cast<int>(window_.size()) > options_.window) window_.pop_front();
  double filtered =
      FilterWindow(std::vector<double>(window_.begin(), window_.end()), options_.gaussian_sigma);
  if (options_.max_change_per_frame > 0.0 && std::isfinite(current_)) {
    filtered = std::clamp(filtered, current_ - options_.max_change_per_frame,
                          current_ + options_.max_change_per_frame);
  }
  current_ = filtered;
  return current_;
}

void ScaleFilter::Reset() {
  window_.clear();
  current_ = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace roadscale
