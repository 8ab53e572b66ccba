#include "roadscale/segmentation/network_tensors.h"

#include <algorithm>
#include <vector>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "roadscale/segmentation/cityscapes.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

std::string ShapeText(const cv::Mat& mat) {
  std::string text = "[";
  for (int i = 0; i < mat.dims; ++i) text += (i > 0 ? ", " : "") + std::to_string(mat.size[i]);
  return text + "]";
}

// Class index -> train id, as a cv::LUT table; indexes beyond the classes map to ignore.
cv::Mat TrainIdTable(const OnnxModelSpec& spec) {
  cv::Mat table(1, 256, CV_8U, cv::Scalar(kIgnoreTrainId));
  for (int c = 0; c < spec.num_classes && c < 256; ++c) {
    table.at<uchar>(c) = static_cast<uchar>(spec.train_ids.empty() ? c : spec.train_ids[c]);
  }
  return table;
}

}  // namespace

cv::Mat MakeInputBlob(const cv::Mat& image, const OnnxModelSpec& spec) {
  CheckOption(
      !image.empty() && image.depth() == CV_8U && (image.channels() == 1 || image.channels() == 3),
      "image", "segmentation needs an 8-bit grey or BGR image");
  cv::Mat converted = image;
  if (spec.input_channels == 3 && image.channels() == 1) {
    cv::cvtColor(image, converted, cv::COLOR_GRAY2BGR);
  } else if (spec.input_channels == 1 && image.channels() == 3) {
    cv::cvtColor(image, converted, cv::COLOR_BGR2GRAY);
  }
  if (spec.input_channels == 3 && spec.channel_order == ChannelOrder::kRgb) {
    // Into a new Mat: `converted` may still share the caller's pixels.
    cv::Mat rgb;
    cv::cvtColor(converted, rgb, cv::COLOR_BGR2RGB);
    converted = rgb;
  }
  const cv::Size input_size(spec.input_width, spec.input_height);
  cv::Mat resized;
  if (converted.size() == input_size) {
    resized = converted;
  } else {
    // Bilinear, as cv::dnn::blobFromImage resizes (the model card's recipe).
    cv::resize(converted, resized, input_size, 0.0, 0.0, cv::INTER_LINEAR);
  }
  std::vector<cv::Mat> channels;
  cv::split(resized, channels);
  for (size_t c = 0; c < channels.size(); ++c) {
    // (value * scale - mean) / std in one pass.
    channels[c].convertTo(channels[c], CV_32F, spec.scale / spec.std[c],
                          -spec.mean[c] / spec.std[c]);
  }
  cv::Mat normalised;
  cv::merge(channels, normalised);
  return cv::dnn::blobFromImage(normalised);
}

cv::Mat OutputToTrainIds(const cv::Mat& output, const OnnxModelSpec& spec,
                         const std::string& yaml_path) {
  const std::string where = spec.file.string();
  if (spec.output == OutputLayout::kScores) {
    if (output.dims != 4 || output.size[0] != 1 || output.size[1] != spec.num_classes ||
        output.type() != CV_32F) {
      ThrowFileError(where, "the network's output is " + ShapeText(output) + ", but " + yaml_path +
                                " says output: scores with num_classes " +
                                std::to_string(spec.num_classes) + ": expected float [1, " +
                                std::to_string(spec.num_classes) + ", height, width]");
    }
    const int height = output.size[2];
    const int width = output.size[3];
    const int pixels = height * width;
    const float* scores = output.ptr<float>();
    cv::Mat best_score(height, width, CV_32F);
    cv::Mat labels(height, width, CV_8U, cv::Scalar(0));
    std::copy(scores, scores + pixels, best_score.ptr<float>());
    float* best = best_score.ptr<float>();
    uchar* label = labels.ptr<uchar>();
    for (int c = 1; c < spec.num_classes; ++c) {
      const float* plane = scores + static_cast<size_t>(c) * pixels;
      for (int i = 0; i < pixels; ++i) {
        if (plane[i] > best[i]) {
          best[i] = plane[i];
          label[i] = static_cast<uchar>(c);
        }
      }
    }
    cv::Mat train_ids;
    cv::LUT(labels, TrainIdTable(spec), train_ids);
    return train_ids;
  }

  const bool shape_ok = (output.dims == 3 && output.size[0] == 1) ||
                        (output.dims == 4 && output.size[0] == 1 && output.size[1] == 1);
  if (!shape_ok || output.channels() != 1) {
    ThrowFileError(where, "the network's output is " + ShapeText(output) + ", but " + yaml_path +
                              " says output: labels: expected [1, height, width] or "
                              "[1, 1, height, width]");
  }
  const int height = output.size[output.dims - 2];
  const int width = output.size[output.dims - 1];
  cv::Mat indices;
  cv::Mat(height, width, output.type(), const_cast<uchar*>(output.ptr()))
      .convertTo(indices, CV_32S);
  const cv::Mat table = TrainIdTable(spec);
  cv::Mat labels(height, width, CV_8U);
  for (int y = 0; y < height; ++y) {
    const int* in = indices.ptr<int>(y);
    uchar* out = labels.ptr<uchar>(y);
    for (int x = 0; x < width; ++x) {
      const int index = in[x];
      out[x] = index >= 0 && index < spec.num_classes ? table.at<uchar>(index)
                                                      : static_cast<uchar>(kIgnoreTrainId);
    }
  }
  return labels;
}

}  // namespace roadscale
