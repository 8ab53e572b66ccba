// calib.txt: ReadKittiCalib and the camera taken from its P0 row.
#include "roadscale/io/kitti_calib.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = roadscale::fuzz::WriteInput(data, size, "calib.txt");
  try {
    const roadscale::KittiCalib calib = roadscale::ReadKittiCalib(path);
    roadscale::KittiCameraFromCalib(calib, 0, 1241, 376, path);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
