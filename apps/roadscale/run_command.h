#pragma once

#include <optional>
#include <string>

namespace roadscale::cli {

// The options of `roadscale run` (see RegisterRunCommand for their meaning); `roadscale demo`
// fills them in for the sequence it renders.
struct RunArguments {
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
  std::string out;
  bool sequential = false;
  std::string title;  // the report's title; default from the input
};

// Runs the pipeline as `roadscale run` does and prints where the outputs are. Throws Error on
// bad input, and after the frames before it were written when a frame fails or the run is
// interrupted (Ctrl-C).
void RunRun(const RunArguments& arguments);

}  // namespace roadscale::cli
