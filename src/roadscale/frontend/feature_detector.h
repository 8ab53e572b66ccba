#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

namespace roadscale {

// Keypoint detectors the frontend can use. Only their detection stage runs: the features are
// tracked with KLT, so descriptors are never computed (SIFT's descriptor would double its cost).
enum class DetectorType { kSift, kOrb, kBrisk, kAkaze, kFast };

// "sift", "orb", "brisk", "akaze" or "fast"; throws Error naming the accepted values otherwise.
DetectorType ParseDetectorType(const std::string& name);
std::string DetectorTypeName(DetectorType type);

struct FeatureDetectorOptions {
  // The paper's detector: SIFT gave the lowest error of the detectors it compared (Table VI).
  DetectorType type = DetectorType::kSift;

  // Feature scattering (libviso2's bucketing, the paper's "feature point scattering"): the
  // image is cut into square cells of `cell_size_px` and each cell keeps at most
  // `max_per_cell` features, strongest response first. Without it the textured buildings and
  // trees take every feature and the low-texture road, which the scale stage needs, gets
  // none. 50 px and 4 per cell give up to ~1000 features on a KITTI frame.
  int cell_size_px = 50;
  int max_per_cell = 4;
  // The cap for features on the road (where a road mask is given). The scale stage needs
  // road points, and road texture is faint: at 4 a cell, the cells of a road between cars
  // (a jam, a city street) hold only a few dozen tracks, of which a keyframe pair keeps a
  // handful. At or below max_per_cell the road gets no more than the rest (the default: 8
  // took the real traffic drive's road tracks from 61 to 74 a frame but KITTI 00/200 from
  // 1.11 % to 1.58 % t_err; docs/benchmark-history.md, "A step that predicts the next").
  int road_max_per_cell = 4;

  // A new feature is kept only this far (pixels) from existing tracks and from the other new
  // features: two tracks on the same patch add cost and no information.
  double min_distance_px = 8.0;

  // Run SIFT on the half-resolution image (positions scaled back). OpenCV's SIFT first
  // doubles its input, so its finest octave is then the full-resolution image instead of an
  // upsampled one: features of sub-pixel scale, which KLT's 21 px windows do not need, are
  // skipped, and detection costs about a fifth (a KITTI frame on this loaded 2-core machine:
  // ~500 ms against ~110 ms). The other detectors run at full resolution.
  bool sift_half_resolution = true;

  // Features nearer than this to the image border are dropped: KLT's window (21 px) would
  // reach outside the image.
  int border_px = 10;

  // SIFT's contrast threshold (OpenCV's default is 0.04). Lower, because the grid cap, not
  // the threshold, decides which features survive: a cell of faint road texture must still
  // get candidates.
  double sift_contrast_threshold = 0.02;
  // Intensity threshold of the FAST / AGAST corner test inside FAST, ORB and BRISK (OpenCV's
  // defaults: 10, 20 and 30). Low for the same reason as the SIFT contrast.
  int corner_threshold = 10;

  // Throws Error naming the first invalid option.
  void Check() const;
};

// Detects features spread over the image with a cap per grid cell.
class FeatureDetector {
 public:
  explicit FeatureDetector(const FeatureDetectorOptions& options);

  // Features of a grey CV_8UC1 `image` where `mask` (CV_8UC1 of the image's size, non-zero =
  // allowed; empty = whole image) allows them. Cells already holding `max_per_cell` of the
  // `existing` points get no new feature, other cells are topped up, and no new feature lies
  // within `min_distance_px` of an existing point. Features on `road_mask` (same type and
  // size; empty = no road known) are capped at `road_max_per_cell` instead. Throws Error on an
  // image or mask of the wrong type or size.
  std::vector<cv::Point2f> Detect(const cv::Mat& image, const cv::Mat& mask,
                                  const std::vector<cv::Point2f>& existing = {},
                                  const cv::Mat& road_mask = cv::Mat()) const;

  const FeatureDetectorOptions& options() const { return options_; }

 private:
  FeatureDetectorOptions options_;
  cv::Ptr<cv::Feature2D> detector_;
};

}  // namespace roadscale
