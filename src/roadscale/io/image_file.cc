#include "roadscale/io/image_file.h"

#include <cerrno>

#include <fcntl.h>
#include <unistd.h>

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

void WriteImageFile(const std::string& path, const cv::Mat& image) {
  // Opened here first: where it cannot be, OpenCV would print a warning of its own.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) ThrowFileError(path, std::string("cannot write image: ") + ErrnoReason(errno));
  ::close(fd);
  bool written = false;
  try {
    written = WriteImage(path, image);
  } catch (const cv::Exception&) {
    // OpenCV's message spans lines and names its own source file; the path says enough.
    written = false;
  }
  if (!written) {
    ::unlink(path.c_str());  // no empty or cut file where an image was expected
    ThrowFileError(path, "cannot write image");
  }
}

}  // namespace roadscale
