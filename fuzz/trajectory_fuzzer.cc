// Trajectory files: the KITTI and TUM parsers and the format detection of `rescale`, on the
// same bytes.
#include "roadscale/io/trajectory_io.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text = roadscale::fuzz::Text(data, size);
  for (const auto& parse : {roadscale::ParseKittiTrajectory, roadscale::ParseTumTrajectory}) {
    try {
      parse(text, "poses.txt");
    } catch (const roadscale::Error&) {
    }
  }
  try {
    roadscale::DetectTrajectoryFormat(text, "poses.txt");
  } catch (const roadscale::Error&) {
  }
  return 0;
}
