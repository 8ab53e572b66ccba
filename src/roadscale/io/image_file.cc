#include "roadscale/io/image_file.h"

#include "roadscale/io/image_codecs.h"
#include "roadscale/io/png_structure.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"

namespace roadscale {

cv::Mat ReadImageFile(const std::string& path, int flags, const std::string& what) {
  const std::string bytes = ReadInputFile(path, what);
  if (bytes.empty()) ThrowFileError(path, "cannot decode " + what + " (the file is empty)");
  const std::string problem = PngStructureProblem(bytes);
  if (!problem.empty()) ThrowFileError(path, "cannot decode " + what + " (" + problem + ")");
  cv::Mat image = DecodeImage(bytes, flags);
  if (image.empty()) {
    ThrowFileError(path, "cannot decode " + what + " (corrupt, truncated or not an image)");
  }
  return image;
}

}  // namespace roadscale
