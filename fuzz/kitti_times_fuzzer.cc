// times.txt: ReadKittiTimes.
#include "roadscale/io/kitti_calib.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = roadscale::fuzz::WriteInput(data, size, "times.txt");
  try {
    roadscale::ReadKittiTimes(path);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
