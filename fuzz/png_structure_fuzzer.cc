// The PNG chunk walk that runs on every frame before decoding: PngStructureProblem.
#include "roadscale/io/png_structure.h"

#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  roadscale::PngStructureProblem(roadscale::fuzz::Text(data, size));
  return 0;
}
