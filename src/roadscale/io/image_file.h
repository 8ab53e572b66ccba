#pragma once

#include <string>

#include <opencv2/core.hpp>

namespace roadscale {

// Reads and decodes one image file (cv::IMREAD_* `flags`), the way every frame and label
// image is read: the reason a file cannot be read is named ("PATH: cannot open WHAT: is a
// directory", "permission denied", ...), and an empty file or a PNG that is truncated or
// damaged is reported before decoding, so that libpng and OpenCV print nothing of their own
// ("PATH: cannot decode WHAT (truncated in chunk IDAT)"). Throws Error.
cv::Mat ReadImageFile(const std::string& path, int flags, const std::string& what);

}  // namespace roadscale
