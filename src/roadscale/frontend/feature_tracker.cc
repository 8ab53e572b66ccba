#include "roadscale/frontend/feature_tracker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "roadscale/util/elapsed_time.h"
#include "roadscale/util/error.h"

#include <Eigen/Geometry>

namespace roadscale {
namespace {

// Whether `pixel`, rounded and clamped to the image, lies on the non-zero part of `mask`.
bool IsOnMask(const cv::Mat& mask, const Eigen::Vector2d& pixel) {
  const int x = std::clamp(static_cast<int>(std::lround(pixel.x())), 0, mask.cols - 1);
  const int y = std::clamp(static_cast<int>(std::lround(pixel.y())), 0, mask.rows - 1);
  return mask.at<unsigned char>(y, x) != 0;
}

// Throws Error unless `mask` is empty or 8-bit single channel of `size`.
void CheckDynamicMask(const cv::Mat& mask, const cv::Size& size, int frame_index) {
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != size)) {
    throw Error("frame " + std::to_string(frame_index) +
                ": the dynamic mask must be 8-bit single channel and of the image's size");
  }
}

// Tracks followed over at least two frames: the ones with a correspondence.
int CountTracked(const std::vector<roadscale::Track>& tracks) {
  return static_cast<int>(
      std::count_if(tracks.begin(), tracks.end(),
                    [](const roadscale::Track& track) { return track.length() >= 2; }));
}

cv::Point2f ToCv(const Eigen::Vector2d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y())};
}

}  // namespace

void FeatureTrackerOptions::Check() const {
  detector.Check();
  klt.Check();
  CheckOption(redetect_below >= 0, "frontend.redetect_below", "must be non-negative");
}

FeatureTracker::FeatureTracker(const FeatureTrackerOptions& options)
    : options_(options), detector_(options.detector) {
  options_.Check();
}

int FeatureTracker::Track(int frame_index, const cv::Mat& image, const cv::Mat& dynamic_mask,
                          const Eigen::Matrix3d& prediction) {
  if (image.empty() || image.type() != CV_8UC1) {
    throw Error("frame " + std::to_string(frame_index) + ": tracking needs an 8-bit grey image");
  }
  if (!image_.empty() && image.size() != image_.size()) {
    throw Error("frame " + std::to_string(frame_index) + ": image size " +
                std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                " differs from the previous frame's " + std::to_string(image_.cols) + "x" +
                std::to_string(image_.rows));
  }
  CheckDynamicMask(dynamic_mask, image.size(), frame_index);
  if (current_frame_ >= 0 && frame_index != current_frame_ + 1) {
    throw Error("frame " + std::to_string(frame_index) + " does not follow frame " +
                std::to_string(current_frame_) + ": the tracker needs consecutive frames");
  }

  stats_ = TrackerFrameStats();
  auto start = std::chrono::steady_clock::now();
  KltPyramid pyramid = BuildKltPyramid(image, options_.klt);
  stats_.pyramid_ms = MillisecondsSince(start);

  if (!pyramid_.empty() && !tracks_.empty()) {
    start = std::chrono::steady_clock::now();
    std::vector<cv::Point2f> prev_points;
    prev_points.reserve(tracks_.size());
    for (const roadscale::Track& track : tracks_) prev_points.push_back(ToCv(track.pixels.back()));
    std::vector<cv::Point2f> predicted;
    if (!prediction.isIdentity(1e-12)) {
      predicted.reserve(prev_points.size());
      for (const roadscale::Track& track : tracks_) {
        const Eigen::Vector3d h = prediction * track.pixels.back().homogeneous();
        predicted.push_back(h.z() > 0.0 ? ToCv(h.hnormalized()) : ToCv(track.pixels.back()));
      }
    }
    const KltResult klt = TrackKlt(pyramid_, pyramid, prev_points, predicted, options_.klt);

    std::vector<roadscale::Track> alive;
    alive.reserve(tracks_.size());
    for (size_t i = 0; i < tracks_.size(); ++i) {
      if (!klt.ok[i]) {
        ++stats_.lost;
        continue;
      }
      alive.push_back(std::move(tracks_[i]));
      alive.back().pixels.emplace_back(klt.points[i].x, klt.points[i].y);
    }
    tracks_ = std::move(alive);
    stats_.tracking_ms = MillisecondsSince(start);
  } else {
    tracks_.clear();
  }

  pyramid_ = std::move(pyramid);
  image_ = image.clone();
  current_frame_ = frame_index;
  DropOnMask(dynamic_mask);
  return stats_.tracked;
}

void FeatureTracker::DropOnMask(const cv::Mat& dynamic_mask) {
  CheckDynamicMask(dynamic_mask, image_.size(), current_frame_);
  if (!dynamic_mask.empty()) {
    const auto start = std::chrono::steady_clock::now();
    // Only tracks carried into this frame: one born here was detected off the mask.
    const auto on_mask = [&](const roadscale::Track& track) {
      if (track.last_frame() != current_frame_ || track.length() < 2) return false;
      return IsOnMask(dynamic_mask, track.pixels.back());
    };
    const size_t before = tracks_.size();
    tracks_.erase(std::remove_if(tracks_.begin(), tracks_.end(), on_mask), tracks_.end());
    stats_.dropped_dynamic += static_cast<int>(before - tracks_.size());
    stats_.tracking_ms += MillisecondsSince(start);
  }
  stats_.tracked = CountTracked(tracks_);
}

std::vector<int64_t> FeatureTracker::DropOnMaskAt(int frame_index, const cv::Mat& dynamic_mask) {
  std::vector<int64_t> dropped;
  CheckDynamicMask(dynamic_mask, image_.size(), frame_index);
  if (dynamic_mask.empty()) return dropped;
  const auto on_mask = [&](const roadscale::Track& track) {
    if (frame_index < track.first_frame || frame_index > track.last_frame()) return false;
    if (!IsOnMask(dynamic_mask,
                  track.pixels[static_cast<size_t>(frame_index - track.first_frame)])) {
      return false;
    }
    dropped.push_back(track.id);
    return true;
  };
  tracks_.erase(std::remove_if(tracks_.begin(), tracks_.end(), on_mask), tracks_.end());
  stats_.dropped_dynamic += static_cast<int>(dropped.size());
  stats_.tracked = CountTracked(tracks_);
  return dropped;
}

int FeatureTracker::Detect(const cv::Mat& detection_mask, bool force, const cv::Mat& road_mask) {
  if (image_.empty()) throw Error("feature detection before the first frame was tracked");
  if (!force && static_cast<int>(tracks_.size()) >= options_.redetect_below) return 0;

  const auto start = std::chrono::steady_clock::now();
  std::vector<cv::Point2f> existing;
  existing.reserve(tracks_.size());
  for (const roadscale::Track& track : tracks_) existing.push_back(ToCv(track.pixels.back()));
  const std::vector<cv::Point2f> features =
      detector_.Detect(image_, detection_mask, existing, road_mask);
  for (const cv::Point2f& p : features) {
    roadscale::Track track;
    track.id = next_id_++;
    track.first_frame = current_frame_;
    track.pixels.emplace_back(p.x, p.y);
    tracks_.push_back(std::move(track));
  }
  stats_.detected = static_cast<int>(features.size());
  stats_.detection_ms = MillisecondsSince(start);
  return stats_.detected;
}

void FeatureTracker::Drop(const std::vector<int64_t>& ids) {
  if (ids.empty()) return;
  std::vector<int64_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  tracks_.erase(std::remove_if(tracks_.begin(), tracks_.end(),
                               [&](const roadscale::Track& track) {
                                 return std::binary_search(sorted.begin(), sorted.end(), track.id);
                               }),
                tracks_.end());
}

}  // namespace roadscale
