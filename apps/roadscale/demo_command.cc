// `roadscale demo`: the whole system on a sequence it renders itself, from a fresh clone and
// without any download: synthetic scene (exact ground truth and label images) -> roadscale
// run with segmentation from the labels -> metrics and the HTML report.
#include <filesystem>
#include <iostream>
#include <string>

#include "roadscale/synth/scene_options.h"
#include "roadscale/synth/scene_writer.h"
#include "roadscale/synth/scene_yaml.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/util/error.h"

#include "commands.h"
#include "run_command.h"

namespace roadscale::cli {
namespace {

struct DemoArguments {
  std::string out = "roadscale-demo";
  int frames = 150;
  std::string preset = "urban";
  std::string segmentation = "labels";
  uint64_t seed = 1;
  bool sequential = false;
};

void RunDemo(const DemoArguments& arguments) {
  CheckOption(arguments.frames >= 10 && arguments.frames <= 100000, "--frames",
              "must be 10..100000");
  if (arguments.segmentation != "labels" && arguments.segmentation != "network" &&
      arguments.segmentation != "none") {
    throw Error("unknown --segmentation '" + arguments.segmentation +
                "' (expected labels, network or none)");
  }
  const std::filesystem::path out = arguments.out;
  const std::filesystem::path data = out / "data";
  std::cout << "Rendering " << arguments.frames << " frames of the '" << arguments.preset
            << "' preset into " << data.string() << " ...\n"
            << std::flush;
  synth::SceneOptions options = synth::LoadSceneOptions(arguments.preset, "");
  options.seed = arguments.seed;
  synth::SyntheticScene scene(options, arguments.frames);
  synth::SceneWriterOptions writer;
  writer.out_dir = data.string();
  writer.progress = false;
  synth::WriteSyntheticSequence(scene, writer);

  const std::filesystem::path sequence = data / "sequences" / writer.sequence;
  RunArguments run;
  run.kitti = sequence.string();
  run.out = (out / "run").string();
  run.sequential = arguments.sequential;
  run.title = "roadscale demo: synthetic '" + arguments.preset + "' sequence, " +
              std::to_string(arguments.frames) + " frames";
  if (arguments.segmentation == "labels") run.labels = (sequence / "semantic").string();
  if (arguments.segmentation == "none") run.no_segmentation = true;
  std::cout << "Running roadscale run --kitti " << run.kitti
            << (run.labels.empty() ? std::string() : " --labels " + run.labels)
            << (run.no_segmentation ? " --no-segmentation" : "") << " --out " << run.out << "\n"
            << std::flush;
  RunRun(run);
  std::cout << "\nThe report: " << std::filesystem::absolute(out / "run" / "report.html").string()
            << " (open it in a browser)\n";
}

}  // namespace

void RegisterDemoCommand(CLI::App& app) {
  auto arguments = std::make_shared<DemoArguments>();
  CLI::App* command = app.add_subcommand(
      "demo",
      "Render a synthetic driving sequence (exact ground truth and label images), run the full "
      "pipeline on it with segmentation from the labels, evaluate it and write the HTML "
      "report. Needs no data: about half a minute on a 2-core machine.");
  command->add_option("--out", arguments->out, "Output folder (data/ and run/ inside)")
      ->capture_default_str();
  command->add_option("--frames", arguments->frames, "Number of frames to render (10 Hz)")
      ->capture_default_str();
  std::string presets;
  for (const std::string& name : synth::PresetNames())
    presets += (presets.empty() ? "" : "|") + name;
  command->add_option("--preset", arguments->preset, "Scene preset: " + presets)
      ->capture_default_str();
  command
      ->add_option("--segmentation", arguments->segmentation,
                   "labels = the rendered label images, network = the shared ESPNetv2 model "
                   "(config/models/espnetv2_512x256.yaml), none = no segmentation")
      ->capture_default_str();
  command->add_option("--seed", arguments->seed, "Scene seed")->capture_default_str();
  command->add_flag("--sequential", arguments->sequential,
                    "Run the pipeline's stages on one thread (same output)");
  command->callback([arguments] { RunDemo(*arguments); });
}

}  // namespace roadscale::cli
