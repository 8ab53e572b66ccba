#include "roadscale/batch/drive_run.h"

#include <cstdint>
#include <cstdio>

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

std::string DriveFingerprint(const BatchDrive& drive, const std::string& roadscale_version) {
  Fnv1a hash;
  hash.Add(roadscale_version);
  for (const std::string& argument : RunArguments(drive, "")) hash.Add(argument);
  for (const std::string* path : {&drive.config, &drive.camera, &drive.model}) {
    hash.Add(path->empty() ? std::string() : ReadInputFile(*path, "file of drive " + drive.name));
  }
  return hash.Hex();
}

}  // namespace roadscale::batch
