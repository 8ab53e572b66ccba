// The run config (--config): ReadRunConfig, and writing the result back as config_used.yaml.
#include "roadscale/config/config_yaml.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = roadscale::fuzz::WriteInput(data, size, "config.yaml");
  try {
    roadscale::RunConfig config;
    roadscale::ReadRunConfig(path, &config);
    roadscale::FormatRunConfig(config);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
