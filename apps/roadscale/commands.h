#pragma once

#include <CLI/CLI.hpp>

namespace roadscale::cli {

// Each subcommand lives in its own file and adds itself to the application through one of
// these functions. A subcommand's callback throws roadscale::Error on bad input; main()
// turns it into one line on stderr and a non-zero exit code.

// `roadscale batch`: many drives as `roadscale run` would run them, resumable, with a summary.
void RegisterBatchCommand(CLI::App& app);

// `roadscale demo`: renders a synthetic sequence, runs the pipeline, writes the report.
void RegisterDemoCommand(CLI::App& app);

// `roadscale eval`: KITTI devkit metric, ATE, RPE and drift of an estimated trajectory.
void RegisterEvalCommand(CLI::App& app);

// `roadscale run`: the visual odometry on a sequence, poses written while it runs.
void RegisterRunCommand(CLI::App& app);

// `roadscale rescale`: another VO's trajectory given its metric scale from the road plane.
void RegisterRescaleCommand(CLI::App& app);

// `roadscale segment`: label images and overlays from a segmentation model.
void RegisterSegmentCommand(CLI::App& app);

// `roadscale synth`: synthetic driving sequences with exact ground truth.
void RegisterSynthCommand(CLI::App& app);

}  // namespace roadscale::cli
