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

// Encodes `image` in the format of the path's extension and writes it (cv::imwrite), the way
// every image roadscale writes is written: any failure, an exception of OpenCV's included, is
// one line naming the file ("PATH: cannot write image: permission denied"). Throws Error.
void WriteImageFile(const std::string& path, const cv::Mat& image);

}  // namespace roadscale
