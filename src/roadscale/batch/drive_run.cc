#include "roadscale/batch/drive_run.h"

#include <cstdint>
#include <cstdio>

#include "roadscale/config/config_yaml.h"
#include "roadscale/segmentation/segmentation_model.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"

namespace roadscale::batch {
namespace {

// 64-bit FNV-1a: stable across builds and machines (std::hash is neither), and plenty to
// notice a change; this is no defence against anyone forging a collision.
class Fnv1a {
 public:
  void Add(const std::string& bytes) {
    for (const char c : bytes) {
      hash_ ^= static_cast<unsigned char>(c);
      hash_ *= 0x100000001b3ULL;
    }
    // A separator, so that ("ab", "c") and ("a", "bc") differ.
    hash_ ^= 0xffU;
    hash_ *= 0x100000001b3ULL;
  }

  std::string Hex() const {
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(hash_));
    return text;
  }

 private:
  uint64_t hash_ = 0xcbf29ce484222325ULL;
};

void AddOption(std::vector<std::string>* arguments, const char* option, const std::string& value) {
  if (value.empty()) return;
  arguments->push_back(option);
  arguments->push_back(value);
}

// The h0 as run reads it back: the shortest text that gives the same double.
std::string FormatH0(double h0) {
  char text[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, h0);
    if (std::stod(text) == h0) break;
  }
  return text;
}

}  // namespace

std::vector<std::string> RunArguments(const RunRequest& run, const std::string& out_dir) {
  std::vector<std::string> arguments = {"run"};
  AddOption(&arguments, "--kitti", run.kitti);
  AddOption(&arguments, "--images", run.images);
  AddOption(&arguments, "--video", run.video);
  AddOption(&arguments, "--camera", run.camera);
  AddOption(&arguments, "--config", run.config);
  AddOption(&arguments, "--model", run.model);
  AddOption(&arguments, "--labels", run.labels);
  if (run.no_segmentation) arguments.push_back("--no-segmentation");
  if (run.scale) AddOption(&arguments, "--scale", *run.scale);
  if (run.detector) AddOption(&arguments, "--detector", *run.detector);
  if (run.h0) AddOption(&arguments, "--h0", FormatH0(*run.h0));
  AddOption(&arguments, "--frames", run.frames);
  if (run.sequential) arguments.push_back("--sequential");
  AddOption(&arguments, "--out", out_dir);
  return arguments;
}

std::string DriveModelFile(const BatchDrive& drive, const std::string& default_model) {
  if (!drive.labels.empty() || drive.no_segmentation) return {};
  if (!drive.model.empty()) return drive.model;
  RunConfig config;
  if (!drive.config.empty()) ReadRunConfig(drive.config, &config);
  if (!config.labels.empty() || config.segmentation.model == "none") return {};
  return config.segmentation.model == "default" ? default_model : config.segmentation.model;
}

std::string DriveFingerprint(const BatchDrive& drive, const std::string& roadscale_version,
                             const std::string& default_model) {
  Fnv1a hash;
  hash.Add(roadscale_version);
  for (const std::string& argument : RunArguments(drive, "")) hash.Add(argument);
  const std::string what = "file of drive " + drive.name;
  for (const std::string* path : {&drive.config, &drive.camera}) {
    hash.Add(path->empty() ? std::string() : ReadInputFile(*path, what));
  }
  const std::string model_file = DriveModelFile(drive, default_model);
  std::string model_yaml;
  std::string weights;
  try {
    if (!model_file.empty()) {
      model_yaml = ReadInputFile(model_file, what);
      const SegmentationModel model = ReadSegmentationModel(model_file);
      if (model.backend == SegmentationBackend::kOnnx) {
        weights = ReadInputFile(model.onnx.file.string(), what);
      }
    }
  } catch (const Error&) {
    if (model_file != default_model) throw;
    model_yaml.clear();
    weights.clear();
  }
  hash.Add(model_yaml);
  hash.Add(weights);
  return hash.Hex();
}

}  // namespace roadscale::batch
