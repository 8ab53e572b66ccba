#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace roadscale {

// Cityscapes train ids, the label space of every label map in roadscale (CV_8U).
inline constexpr int kRoadTrainId = 0;
inline constexpr int kNumCityscapesTrainIds = 20;  // 0..18 plus 19 "background"
// Pixels a label source says nothing about (Cityscapes "ignore", label ids without a
// train id: parking, guard rail, ego vehicle, ...).
inline constexpr int kIgnoreTrainId = 255;

// person, rider, car, truck, bus, train, motorcycle, bicycle: objects that may move.
std::vector<int> CityscapesDynamicTrainIds();

// "road", "car", ...; "background" for 19 and "ignore" for anything else.
std::string CityscapesTrainIdName(int train_id);

// A 1x256 CV_8U lookup table (for cv::LUT) from Cityscapes label ids (road = 7, car = 26,
// ...) to train ids; label ids without a train id map to kIgnoreTrainId.
cv::Mat CityscapesLabelIdToTrainIdTable();

// The Cityscapes colour of a train id, as BGR; black for ignore and unknown ids.
cv::Vec3b CityscapesTrainIdColour(int train_id);

// Paints a train-id label map (CV_8U) with the Cityscapes palette (CV_8UC3, BGR).
cv::Mat ColouriseTrainIds(const cv::Mat& labels);

// The palette colours blended over the image (grey or BGR) with the given weight of the
// colours, for a person to check what the network sees. Ignore pixels show the image.
cv::Mat OverlayTrainIds(const cv::Mat& image, const cv::Mat& labels, double colour_weight = 0.5);

}  // namespace roadscale
