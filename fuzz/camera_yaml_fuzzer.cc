// The camera YAML of --images and --video: ReadCameraYaml.
#include "roadscale/io/camera_setup.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = roadscale::fuzz::WriteInput(data, size, "camera.yaml");
  try {
    roadscale::ReadCameraYaml(path);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
