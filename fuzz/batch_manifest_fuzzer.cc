// The batch manifest (roadscale batch --manifest): ReadBatchManifest, with the folders and
// files its seeds name beside it, so that inputs get past the path checks.
#include <filesystem>

#include "roadscale/batch/manifest.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool prepared = [] {
    std::filesystem::create_directories(roadscale::fuzz::WorkDir() / "seq");
    roadscale::fuzz::WriteInput(nullptr, 0, "cam.yaml");
    return true;
  }();
  (void)prepared;
  const std::string path = roadscale::fuzz::WriteInput(data, size, "manifest.yaml");
  try {
    roadscale::batch::ReadBatchManifest(path);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
