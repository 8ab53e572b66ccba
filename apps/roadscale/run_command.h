#pragma once

#include <string>

#include "roadscale/pipeline/run_request.h"

namespace roadscale::cli {

// The options of `roadscale run`: the run's request, its output folder and the report's
// title (default from the input); `roadscale demo` fills them in for the sequence it renders.
struct RunArguments : RunRequest {
  std::string out;
  std::string title;
};

// Runs the pipeline as `roadscale run` does and prints where the outputs are. Throws Error on
// bad input, and after the frames before it were written when a frame fails or the run is
// interrupted (Ctrl-C).
void RunRun(const RunArguments& arguments);

// The segmentation model YAML run loads when none is named (the shipped ESPNetv2 file:
// PREFIX/share/roadscale/config/models/ beside an installed command, else the source tree's
// config/models/); run goes without segmentation when it cannot be read.
std::string DefaultModelPath();

}  // namespace roadscale::cli
