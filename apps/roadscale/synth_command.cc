// `roadscale synth`: renders a synthetic driving sequence with exact ground truth in KITTI's
// layout (docs/synthetic_scenes.md).
#include <string>
#include <vector>

#include "roadscale/synth/scene_options.h"
#include "roadscale/synth/scene_writer.h"
#include "roadscale/synth/scene_yaml.h"
#include "roadscale/synth/synthetic_scene.h"
#include "roadscale/util/error.h"

#include "commands.h"

namespace roadscale::cli {
namespace {

struct SynthArguments {
  std::string preset;
  int frames = 100;
  uint64_t seed = 1;
  bool seed_given = false;
  std::string out;
  std::string sequence = "00";
  std::string scene;
  bool colour = false;
  int threads = 0;
  std::vector<double> distortion;
};

void RunSynth(const SynthArguments& arguments) {
  CheckOption(arguments.frames >= 1 && arguments.frames <= 1000000, "--frames",
              "must be 1..1000000");
  synth::CheckSequenceName(arguments.sequence);
  synth::SceneOptions options = synth::LoadSceneOptions(arguments.preset, arguments.scene);
  if (arguments.seed_given || arguments.scene.empty()) options.seed = arguments.seed;
  if (arguments.threads > 0) options.image.threads = arguments.threads;
  synth::SyntheticScene scene(options, arguments.frames);
  synth::SceneWriterOptions writer;
  writer.out_dir = arguments.out;
  writer.sequence = arguments.sequence;
  writer.colour = arguments.colour;
  writer.distortion = arguments.distortion;
  writer.progress = true;
  synth::WriteSyntheticSequence(scene, writer);
}

}  // namespace

void RegisterSynthCommand(CLI::App& app) {
  auto arguments = std::make_shared<SynthArguments>();
  CLI::App* command = app.add_subcommand(
      "synth",
      "Render a synthetic driving sequence with exact ground truth (poses, road planes, "
      "semantic labels, depth, moving masks) in KITTI's layout.");
  std::string presets;
  for (const std::string& name : synth::PresetNames())
    presets += (presets.empty() ? "" : "|") + name;
  command->add_option(
      "--preset", arguments->preset,
      "Scene preset: " + presets + " (default: the scene file's `preset`, else urban)");
  command->add_option("--frames", arguments->frames, "Number of frames (10 Hz by default)")
      ->capture_default_str();
  CLI::Option* seed = command->add_option(
      "--seed", arguments->seed,
      "Random seed: the same seed and options give byte-identical files (default 1, or the "
      "scene file's `seed`)");
  command->add_option("--out", arguments->out, "Output dataset folder (KITTI layout)")->required();
  command->add_option("--sequence", arguments->sequence, "Sequence folder name (digits)")
      ->capture_default_str();
  command->add_option("--scene", arguments->scene,
                      "YAML scene file overriding the preset (keys in docs/synthetic_scenes.md; "
                      "default: none)");
  command->add_flag("--colour,--color", arguments->colour,
                    "Also write colour frames to image_2 (default: off)");
  command->add_option("--threads", arguments->threads,
                      "Rendering threads; the output does not depend on it (default: the "
                      "scene's Image.threads, 2)");
  command
      ->add_option("--distortion", arguments->distortion,
                   "Render through a lens with this distortion, OpenCV's k1,k2,p1,p2,k3 (or 8 "
                   "with k4,k5,k6), written to camera.yaml; calib.txt keeps the pinhole camera "
                   "of the undistorted image (default: none)")
      ->delimiter(',');
  command->callback([arguments, seed] {
    arguments->seed_given = seed->count() > 0;
    RunSynth(*arguments);
  });
}

}  // namespace roadscale::cli
