// A synthetic scene file (`roadscale synth --scene`): LoadSceneOptions.
#include "roadscale/synth/scene_yaml.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = roadscale::fuzz::WriteInput(data, size, "scene.yaml");
  try {
    roadscale::synth::LoadSceneOptions("", path);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
