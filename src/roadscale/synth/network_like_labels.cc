#include "roadscale/synth/network_like_labels.h"

#include <opencv2/imgproc.hpp>

#include "roadscale/synth/mesh.h"

namespace roadscale::synth {
namespace {

// Cityscapes train ids 11 (person) to 18 (bicycle): the classes that move.
constexpr int kLastMovingTrainId = 18;

cv::Mat MovingObjects(const cv::Mat& labels) {
  cv::Mat mask;
  cv::inRange(labels, label::kPerson, kLastMovingTrainId, mask);
  return mask;
}

}  // namespace

NetworkLikeLabels::NetworkLikeLabels(const LabelErrorOptions& options, uint64_t seed)
    : options_(options), rng_(Rng(seed).Fork(0x6c6162656c73ULL)) {
  options_.Check();
}

cv::Mat NetworkLikeLabels::Next(const cv::Mat& labels) {
  earlier_.push_back(labels.clone());
  while (static_cast<int>(earlier_.size()) > options_.dynamic_lag_frames + 1) {
    earlier_.pop_front();
  }
  // Late outlines: the objects where the frame `dynamic_lag_frames` before had them (fewer at
  // the start of the drive); what they cover now beyond that reads as road.
  const cv::Mat& late = earlier_.front();
  cv::Mat out = labels.clone();
  const cv::Mat now_moving = MovingObjects(labels);
  out.setTo(label::kRoad, now_moving);
  cv::Mat moving = MovingObjects(late);
  if (options_.dynamic_erosion_px > 0) {
    const int size = 2 * options_.dynamic_erosion_px + 1;
    cv::erode(moving, moving, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size)));
  }
  // Flicker: each object missed in this frame with probability dynamic_dropout.
  if (options_.dynamic_dropout > 0.0) {
    cv::Mat components;
    const int count = cv::connectedComponents(moving, components, 8, CV_32S);
    for (int i = 1; i < count; ++i) {
      if (rng_.Bernoulli(options_.dynamic_dropout)) moving.setTo(0, components == i);
    }
  }
  late.copyTo(out, moving);
  return out;
}

}  // namespace roadscale::synth
