// A segmentation model description (--model): ReadSegmentationModel. A placeholder net.onnx
// beside the file lets `file: net.onnx` pass, so that the keys after it are reached.
#include "roadscale/segmentation/segmentation_model.h"
#include "roadscale/util/error.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string placeholder =
      roadscale::fuzz::WriteInput(reinterpret_cast<const uint8_t*>("onnx"), 4, "net.onnx");
  const std::string path = roadscale::fuzz::WriteInput(data, size, "model.yaml");
  try {
    roadscale::ReadSegmentationModel(path);
  } catch (const roadscale::Error&) {
  }
  return 0;
}
