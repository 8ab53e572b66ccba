#pragma once

#include <cstddef>
#include <deque>
#include <vector>

namespace roadscale {

struct ScaleFilterOptions {
  // q of eq. (14): how many of the latest raw scales the filter sees.
  int window = 5;
  // sigma of eq. (15), in frames (window positions). The paper's value is 5; its public code
  // uses 3. 0 skips the Gaussian smoothing (median only).
  double gaussian_sigma = 5.0;
  // The public code's clamp: the filtered scale changes by at most this much per frame
  // (0.3 there). 0 (the paper, the default) does not clamp.
  double max_change_per_frame = 0.0;

  void Check() const;
};

// The mixed filter of eqs. (14)-(16). Eq. (15) as printed evaluates a Gaussian density at the
// scale values themselves, which is not a filter of them; it is read here as what the text
// says: "apply a gaussian filter on [the queue of scales], and then apply a median filter".
// The window's values are smoothed by a Gaussian over the window positions (a 1-D
// convolution with weights exp(-(i-j)^2 / (2 sigma^2)), renormalised where the kernel runs
// past either end of the window), and the filtered scale is the median of the smoothed
// window (the mean of the two middle values for an even count).
class ScaleFilter {
 public:
  explicit ScaleFilter(const ScaleFilterOptions& options = {});

  // Adds the newest raw scale and returns the filtered scale. Non-finite or non-positive
  // values are not added; the last filtered scale is returned (NaN before any value).
  double Add(double raw_scale);
  // The last filtered scale (NaN before any value).
  double Current() const { return current_; }
  size_t size() const { return window_.size(); }
  void Reset();

  // The filter's output for a full window, without state: exposed for tests and tools.
  static double FilterWindow(const std::vector<double>& window, double gaussian_sigma);

 private:
  ScaleFilterOptions options_;
  std::deque<double> window_;
  double current_;
};

}  // namespace roadscale
