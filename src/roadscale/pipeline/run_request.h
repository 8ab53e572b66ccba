#pragma once

#include <optional>
#include <string>

namespace roadscale {

// What a run of the odometry is given besides its output folder: the options of `roadscale
// run` (its --help says what each means). Empty strings and unset optionals mean "not given",
// as on run's command line. `roadscale run` fills it from its options, `roadscale batch` from
// a manifest's drive, which it hands to a `roadscale run` process.
struct RunRequest {
  std::string kitti;
  std::string images;
  std::string video;
  std::string camera;
  std::string config;
  std::string model;
  std::string labels;
  bool no_segmentation = false;
  std::optional<std::string> scale;
  std::optional<std::string> detector;
  std::optional<double> h0;
  std::string frames;
  bool sequential = false;
};

}  // namespace roadscale
