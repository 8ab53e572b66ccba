#include "roadscale/frontend/klt_tracker.h"

#include <algorithm>
#include <cmath>

#include <opencv2/video/tracking.hpp>

#include "roadscale/util/error.h"

namespace roadscale {

void KltOptions::Check() const {
  CheckOption(window_size >= 3 && window_size % 2 == 1, "klt.window_size",
              "must be an odd number of at least 3 pixels");
  CheckOption(pyramid_levels >= 0 && pyramid_levels <= 8, "klt.pyramid_levels", "must be in 0..8");
  CheckOption(max_iterations >= 1, "klt.max_iterations", "must be at least 1");
  CheckOption(std::isfinite(epsilon) && epsilon > 0.0, "klt.epsilon", "must be positive");
  CheckOption(std::isfinite(min_eigen_threshold) && min_eigen_threshold >= 0.0,
              "klt.min_eigen_threshold", "must be non-negative");
  CheckOption(std::isfinite(max_forward_backward_error_px) && max_forward_backward_error_px > 0.0,
              "klt.max_forward_backward_error_px", "must be positive");
  CheckOption(backward_pyramid_levels >= 0 && backward_pyramid_levels <= 8,
              "klt.backward_pyramid_levels", "must be in 0..8");
}

KltPyramid BuildKltPyramid(const cv::Mat& image, const KltOptions& options) {
  if (image.empty() || image.type() != CV_8UC1) {
    throw Error("KLT tracking needs a non-empty 8-bit grey image");
  }
  KltPyramid pyramid;
  pyramid.size = image.size();
  cv::buildOpticalFlowPyramid(image, pyramid.levels,
                              cv::Size(options.window_size, options.window_size),
                              options.pyramid_levels);
  return pyramid;
}

KltResult TrackKlt(const KltPyramid& prev, const KltPyramid& cur,
                   const std::vector<cv::Point2f>& prev_points,
                   const std::vector<cv::Point2f>& predicted, const KltOptions& options) {
  if (prev.empty() || cur.empty() || prev.size != cur.size) {
    throw Error("KLT tracking needs two pyramids of images of the same size");
  }
  if (!predicted.empty() && predicted.size() != prev_points.size()) {
    throw Error("KLT tracking: one predicted position per point is needed");
  }
  KltResult result;
  const size_t n = prev_points.size();
  result.ok.assign(n, false);
  result.forward_backward_error.assign(n, 0.0f);
  if (n == 0) return result;

  const cv::Size window(options.window_size, options.window_size);
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS,
                                  options.max_iterations, options.epsilon);
  std::vector<unsigned char> forward_status;
  std::vector<float> error;
  int flags = 0;
  if (!predicted.empty()) {
    result.points = predicted;
    flags = cv::OPTFLOW_USE_INITIAL_FLOW;
  }
  cv::calcOpticalFlowPyrLK(prev.levels, cur.levels, prev_points, result.points, forward_status,
                           error, window, options.pyramid_levels, criteria, flags,
                           options.min_eigen_threshold);

  // Only the forward successes go back; the backward pass starts from the start point, which
  // is the best guess of where the point returns to.
  std::vector<cv::Point2f> forward_points;
  std::vector<cv::Point2f> back_points;
  std::vector<size_t> index;
  for (size_t i = 0; i < n; ++i) {
    if (!forward_status[i]) continue;
    forward_points.push_back(result.points[i]);
    back_points.push_back(prev_points[i]);
    index.push_back(i);
  }
  if (index.empty()) return result;
  std::vector<unsigned char> backward_status;
  cv::calcOpticalFlowPyrLK(cur.levels, prev.levels, forward_points, back_points, backward_status,
                           error, window,
                           std::min(options.backward_pyramid_levels, options.pyramid_levels),
                           criteria, cv::OPTFLOW_USE_INITIAL_FLOW, options.min_eigen_threshold);

  const float max_fb = static_cast<float>(options.max_forward_backward_error_px);
  for (size_t k = 0; k < index.size(); ++k) {
    const size_t i = index[k];
    if (!backward_status[k]) continue;
    const cv::Point2f d = back_points[k] - prev_points[i];
    const float fb = std::sqrt(d.x * d.x + d.y * d.y);
    result.forward_backward_error[i] = fb;
    const cv::Point2f& p = result.points[i];
    const bool inside =
        p.x >= 0.0f && p.y >= 0.0f && p.x <= cur.size.width - 1 && p.y <= cur.size.height - 1;
    result.ok[i] = inside && fb <= max_fb;
  }
  return result;
}

}  // namespace roadscale
