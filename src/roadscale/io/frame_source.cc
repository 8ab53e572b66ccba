#include "roadscale/io/frame_source.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "roadscale/geometry/camera_height.h"
#include "roadscale/io/image_file.h"
#include "roadscale/io/image_undistorter.h"
#include "roadscale/io/kitti_calib.h"
#include "roadscale/util/error.h"
#include "roadscale/util/input_file.h"
#include "roadscale/util/text_parsing.h"

namespace roadscale {
namespace {

namespace fs = std::filesystem;

bool IsAllDigits(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Parses a non-negative integer; false on anything else (sign, junk, overflow).
bool ParseIndex(const std::string& text, size_t* value) {
  if (!IsAllDigits(text)) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return error == std::errc() && end == text.data() + text.size();
}

std::string ToLower(std::string text) {
  for (char& c : text) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return text;
}

std::string SizeText(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

// Orders names as a person numbering frames expects: digit runs compare by value, so
// "img9.png" comes before "img10.png".
bool NaturalLess(const std::string& a, const std::string& b) {
  size_t i = 0;
  size_t j = 0;
  while (i < a.size() && j < b.size()) {
    const bool digit_a = a[i] >= '0' && a[i] <= '9';
    const bool digit_b = b[j] >= '0' && b[j] <= '9';
    if (digit_a && digit_b) {
      size_t end_a = i;
      size_t end_b = j;
      while (end_a < a.size() && a[end_a] >= '0' && a[end_a] <= '9') ++end_a;
      while (end_b < b.size() && b[end_b] >= '0' && b[end_b] <= '9') ++end_b;
      // Compare the runs as numbers without converting (runs may exceed 64 bits).
      size_t start_a = i;
      size_t start_b = j;
      while (start_a + 1 < end_a && a[start_a] == '0') ++start_a;
      while (start_b + 1 < end_b && b[start_b] == '0') ++start_b;
      const size_t length_a = end_a - start_a;
      const size_t length_b = end_b - start_b;
      if (length_a != length_b) return length_a < length_b;
      const int order = a.compare(start_a, length_a, b, start_b, length_b);
      if (order != 0) return order < 0;
      i = end_a;
      j = end_b;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  if ((a.size() - i) != (b.size() - j)) return (a.size() - i) < (b.size() - j);
  return a < b;
}

// Decodes one image; the only place frames are read, so every source reports the same
// errors. `expected_width` 0 skips the size check (used to learn the first image's size).
cv::Mat LoadImage(const std::string& path, bool color, int expected_width, int expected_height) {
  cv::Mat image = ReadImageFile(path, color ? cv::IMREAD_COLOR : cv::IMREAD_GRAYSCALE, "image");
  if (expected_width > 0 && (image.cols != expected_width || image.rows != expected_height)) {
    ThrowFileError(path, "image is " + SizeText(image.cols, image.rows) + " but the sequence's " +
                             "first frame and camera are " +
                             SizeText(expected_width, expected_height));
  }
  return image;
}

// The selected [begin, end) of `total` frames; clamps the end with a note.
std::pair<size_t, size_t> SelectRange(const FrameRange& range, size_t total,
                                      const std::string& what, std::vector<std::string>* notes) {
  if (range.begin >= total) {
    throw Error("--frames " + FormatFrameRange(range) + ": " + what + " has only " +
                std::to_string(total) + " frames (0.." + std::to_string(total - 1) + ")");
  }
  size_t end = range.end;
  if (end > total) {
    if (end != FrameRange::kToEnd) {
      notes->push_back("frames " + FormatFrameRange(range) + " asked for, but " + what +
                       " ends at frame " + std::to_string(total - 1) + ": reading " +
                       std::to_string(range.begin) + ":" + std::to_string(total));
    }
    end = total;
  }
  return {range.begin, end};
}

// times.txt and poses files may run past the images (a partial copy of a sequence) but must
// cover every image.
void CheckRowsCoverImages(const std::string& file, size_t rows, size_t images,
                          const std::string& what, std::vector<std::string>* notes) {
  if (rows < images) {
    ThrowFileError(file, "has " + std::to_string(rows) + " " + what + " but there are " +
                             std::to_string(images) + " images (one row per image needed)");
  }
  if (rows > images) {
    notes->push_back(file + " has " + std::to_string(rows) + " " + what + " for " +
                     std::to_string(images) + " images: using the first " + std::to_string(images) +
                     ", ignoring the rest");
  }
}

std::vector<double> TimestampsFor(const std::string& times_path, size_t images,
                                  std::vector<std::string>* notes) {
  std::vector<double> times;
  if (fs::exists(times_path)) {
    times = ReadKittiTimes(times_path);
    CheckRowsCoverImages(times_path, times.size(), images, "timestamps", notes);
    times.resize(images);
  } else {
    char rate[32];
    std::snprintf(rate, sizeof(rate), "%g", kDefaultFrameRateHz);
    notes->push_back(times_path + " not found: assuming " + std::string(rate) +
                     " Hz (timestamp = index / " + rate + ")");
    times.resize(images);
    for (size_t i = 0; i < images; ++i) times[i] = static_cast<double>(i) / kDefaultFrameRateHz;
  }
  return times;
}

CameraSetup ReadCameraForInput(const FrameSourceOptions& options, const std::string& what) {
  if (options.camera_yaml.empty()) {
    ThrowFileError(options.input,
                   what + " needs a camera YAML file (fx, fy, cx, cy, width, height, h0)");
  }
  CameraSetup setup = ReadCameraYaml(options.camera_yaml);
  if (options.h0) setup.h0 = *options.h0;
  setup.Check();
  return setup;
}

bool SameIntrinsics(const PinholeCamera& a, const PinholeCamera& b) {
  auto close = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::abs(y); };
  return close(a.fx, b.fx) && close(a.fy, b.fy) && close(a.cx, b.cx) && close(a.cy, b.cy) &&
         a.width == b.width && a.height == b.height;
}

// calib.txt has no camera height (see the KittiSequence comment for the order of the
// sources) and no lens distortion (KITTI's are rectified images; a camera YAML can add one).
double KittiCameraHeight(const FrameSourceOptions& options, const fs::path& sequence_dir,
                         const PinholeCamera& calib_camera, std::vector<double>* distortion,
                         std::vector<std::string>* notes) {
  std::string yaml_path = options.camera_yaml;
  if (yaml_path.empty() && fs::exists(sequence_dir / "camera.yaml")) {
    yaml_path = (sequence_dir / "camera.yaml").string();
  }
  std::optional<CameraSetup> yaml;
  if (!yaml_path.empty()) {
    yaml = ReadCameraYaml(yaml_path);
    if (!SameIntrinsics(yaml->camera, calib_camera)) {
      notes->push_back(yaml_path + " has other intrinsics than calib.txt: using calib.txt's, and " +
                       "only the camera height and lens distortion from " + yaml_path);
    }
    *distortion = yaml->distortion;
  }
  if (options.h0) return *options.h0;
  if (yaml) return yaml->h0;
  const double kitti_h0 = CameraSetup().h0;
  char text[64];
  std::snprintf(text, sizeof(text), "%g", kitti_h0);
  notes->push_back(std::string("no camera height given: using KITTI's documented h0 = ") + text +
                   " m");
  return kitti_h0;
}

std::string DescribeRange(size_t first, size_t count) {
  return "frames " + std::to_string(first) + ":" + std::to_string(first + count);
}

}  // namespace

FrameRange ParseFrameRange(const std::string& text) {
  const std::string trimmed = Trim(text);
  FrameRange range;
  if (trimmed.empty() || trimmed == ":") return range;
  const size_t colon = trimmed.find(':');
  if (colon == std::string::npos || trimmed.find(':', colon + 1) != std::string::npos) {
    throw Error("invalid frame range '" + text + "' (expected A:B, A: or :B with frame indexes)");
  }
  const std::string first = Trim(trimmed.substr(0, colon));
  const std::string last = Trim(trimmed.substr(colon + 1));
  if ((!first.empty() && !ParseIndex(first, &range.begin)) ||
      (!last.empty() && !ParseIndex(last, &range.end))) {
    throw Error("invalid frame range '" + text +
                "' (expected non-negative integers: A:B, A: or :B)");
  }
  if (range.begin >= range.end) {
    throw Error("invalid frame range '" + text + "': the end (exclusive) must exceed the begin");
  }
  return range;
}

std::string FormatFrameRange(const FrameRange& range) {
  std::string text = std::to_string(range.begin) + ":";
  if (range.end != FrameRange::kToEnd) text += std::to_string(range.end);
  return text;
}

FrameSourceType ParseFrameSourceType(const std::string& name) {
  if (name == "auto") return FrameSourceType::kAuto;
  if (name == "kitti") return FrameSourceType::kKitti;
  if (name == "images") return FrameSourceType::kImageFolder;
  if (name == "video") return FrameSourceType::kVideo;
  throw Error("unknown input type '" + name + "' (expected auto, kitti, images or video)");
}

FrameSourceType DetectFrameSourceType(const std::string& input) {
  std::error_code error;
  const fs::file_status status = fs::status(input, error);
  if (error || !fs::exists(status)) ThrowFileError(input, "input not found");
  if (!fs::is_directory(status)) return FrameSourceType::kVideo;
  if (fs::is_directory(fs::path(input) / "image_0") ||
      fs::is_directory(fs::path(input) / "image_2")) {
    return FrameSourceType::kKitti;
  }
  return FrameSourceType::kImageFolder;
}

void FrameSourceOptions::Check() const {
  CheckOption(!input.empty(), "input", "a KITTI sequence folder, image folder or video is needed");
  CheckOption(kitti_camera >= -1 && kitti_camera <= 3, "kitti_camera",
              "must be 0..3 (image_N with P_N) or -1 (image_0 when present, else image_2)");
  if (h0) CheckCameraHeight(*h0, "h0");
  CheckOption(frames.begin < frames.end, "frames", "the range is empty");
}

// ---------------------------------------------------------------------------------------

bool ImageFileSequence::Next(Frame* frame) {
  if (next_position_ >= paths_.size()) return false;
  *frame = Read(next_position_);
  ++next_position_;
  return true;
}

Frame ImageFileSequence::Read(size_t position) const {
  if (position >= paths_.size()) {
    throw Error("frame position " + std::to_string(position) + " is out of range (" +
                std::to_string(paths_.size()) + " frames selected)");
  }
  Frame frame;
  frame.index = first_index_ + position;
  frame.timestamp = timestamps_[position];
  frame.path = paths_[position];
  frame.image = LoadImage(frame.path, color_, camera_.camera.width, camera_.camera.height);
  if (undistorter_) frame.image = undistorter_->Undistort(frame.image);
  return frame;
}

void ImageFileSequence::UndistortWithCamerasLens() {
  if (!camera_.distortion.empty()) {
    undistorter_ = std::make_shared<const ImageUndistorter>(camera_.camera, camera_.distortion);
  }
}

// ---------------------------------------------------------------------------------------

KittiSequence::KittiSequence(const FrameSourceOptions& options) {
  options.Check();
  // lexically_normal + parent_path of "" handles a trailing slash in "sequences/00/".
  fs::path dir = fs::path(options.input).lexically_normal();
  if (dir.filename().empty()) dir = dir.parent_path();
  sequence_dir_ = dir.string();
  if (!fs::is_directory(dir)) ThrowFileError(sequence_dir_, "KITTI sequence folder not found");

  kitti_camera_ = options.kitti_camera;
  if (kitti_camera_ < 0) kitti_camera_ = fs::is_directory(dir / "image_0") ? 0 : 2;
  const fs::path image_dir = dir / ("image_" + std::to_string(kitti_camera_));
  if (!fs::is_directory(image_dir)) {
    ThrowFileError(image_dir.string(), options.kitti_camera < 0
                                           ? "folder not found (neither image_0/ nor image_2/)"
                                           : "folder not found");
  }

  // KITTI names frames %06d.png from 000000 without gaps; the file number is the row of
  // times.txt and poses, so a gap would silently pair images with the wrong poses.
  std::vector<size_t> numbers;
  for (const fs::directory_entry& entry : fs::directory_iterator(image_dir)) {
    if (!entry.is_regular_file() || ToLower(entry.path().extension().string()) != ".png") continue;
    const std::string stem = entry.path().stem().string();
    size_t number = 0;
    if (stem.size() != 6 || !ParseIndex(stem, &number)) {
      ThrowFileError(entry.path().string(), "not a KITTI frame name (expected %06d.png)");
    }
    numbers.push_back(number);
  }
  if (numbers.empty()) {
    ThrowFileError(image_dir.string(), "no images (expected 000000.png, 000001.png, ...)");
  }
  std::sort(numbers.begin(), numbers.end());
  auto FramePath = [&image_dir](size_t number) {
    char name[32];
    std::snprintf(name, sizeof(name), "%06zu.png", number);
    return (image_dir / name).string();
  };
  for (size_t i = 0; i < numbers.size(); ++i) {
    if (numbers[i] != i) {
      ThrowFileError(FramePath(i),
                     "missing: the sequence's frames must be numbered from "
                     "000000.png without gaps (" +
                         std::to_string(numbers.size()) + " images found)");
    }
  }
  total_images_ = numbers.size();

  const cv::Mat first = LoadImage(FramePath(0), false, 0, 0);
  const std::string calib_path = (dir / "calib.txt").string();
  camera_.camera = ReadKittiCamera(calib_path, kitti_camera_, first.cols, first.rows);
  try {
    CameraSetup intrinsics;  // h0 and the lens come later, from elsewhere than calib.txt
    intrinsics.camera = camera_.camera;
    intrinsics.Check();
  } catch (const Error& e) {
    ThrowFileError(calib_path, e.what());
  }
  camera_.h0 = KittiCameraHeight(options, dir, camera_.camera, &camera_.distortion, &notes_);
  camera_.Check();
  UndistortWithCamerasLens();
  color_ = options.color;

  const std::vector<double> times =
      TimestampsFor((dir / "times.txt").string(), total_images_, &notes_);

  const std::string sequence_name = dir.filename().string();
  const fs::path poses_path = dir.parent_path().parent_path() / "poses" / (sequence_name + ".txt");
  std::optional<Trajectory> all_poses;
  if (fs::exists(poses_path)) {
    all_poses = ReadKittiTrajectory(poses_path.string());
    CheckRowsCoverImages(poses_path.string(), all_poses->size(), total_images_, "poses", &notes_);
  }

  const auto [begin, end] = SelectRange(options.frames, total_images_, sequence_dir_, &notes_);
  first_index_ = begin;
  for (size_t i = begin; i < end; ++i) {
    paths_.push_back(FramePath(i));
    timestamps_.push_back(times[i]);
  }
  if (all_poses) {
    ground_truth_.emplace();
    ground_truth_->world_from_cam.assign(all_poses->world_from_cam.begin() + begin,
                                         all_poses->world_from_cam.begin() + end);
    ground_truth_->timestamps = timestamps_;
  }
}

std::string KittiSequence::Describe() const {
  return "KITTI sequence " + sequence_dir_ + " (image_" + std::to_string(kitti_camera_) + ", " +
         DescribeRange(first_index_, paths_.size()) + " of " + std::to_string(total_images_) +
         (ground_truth_ ? ", with ground truth)" : ", no ground truth)");
}

// ---------------------------------------------------------------------------------------

ImageFolder::ImageFolder(const FrameSourceOptions& options) {
  options.Check();
  folder_ = options.input;
  if (!fs::is_directory(folder_)) ThrowFileError(folder_, "image folder not found");
  const bool size_from_first_image = options.image_size_only && options.camera_yaml.empty();
  if (!size_from_first_image) camera_ = ReadCameraForInput(options, "an image folder");
  color_ = options.color;

  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder_)) {
    if (!entry.is_regular_file()) continue;
    const std::string extension = ToLower(entry.path().extension().string());
    if (extension == ".png" || extension == ".jpg" || extension == ".jpeg") {
      names.push_back(entry.path().filename().string());
    }
  }
  if (names.empty()) ThrowFileError(folder_, "no images (*.png, *.jpg, *.jpeg)");
  std::sort(names.begin(), names.end(), NaturalLess);

  // Numbered frames with a hole mean a dropped frame: the motion across it would be twice a
  // normal step and the timestamps would pair with the wrong images.
  const bool numbered = std::all_of(names.begin(), names.end(), [](const std::string& name) {
    return IsAllDigits(fs::path(name).stem().string());
  });
  if (numbered) {
    std::vector<size_t> numbers;
    for (const std::string& name : names) {
      size_t number = 0;
      if (!ParseIndex(fs::path(name).stem().string(), &number)) {
        ThrowFileError((fs::path(folder_) / name).string(), "frame number too large");
      }
      numbers.push_back(number);
    }
    for (size_t i = 1; i < numbers.size(); ++i) {
      if (numbers[i] == numbers[i - 1]) {
        ThrowFileError((fs::path(folder_) / names[i]).string(),
                       "has the same frame number as " + names[i - 1]);
      }
      if (numbers[i] != numbers[i - 1] + 1) {
        // Name the hole as the folder would have it: same digits and extension as before.
        const std::string& previous = names[i - 1];
        const fs::path stem = fs::path(previous).stem();
        const int width = static_cast<int>(stem.string().size());
        char number[48];
        std::snprintf(number, sizeof(number), "%0*zu", width, numbers[i - 1] + 1);
        const std::string missing = number + fs::path(previous).extension().string();
        ThrowFileError(
            (fs::path(folder_) / missing).string(),
            "missing: numbered frames must not have gaps (next present: " + names[i] + ")");
      }
    }
  }
  total_images_ = names.size();

  const std::string first_path = (fs::path(folder_) / names.front()).string();
  const cv::Mat first = LoadImage(first_path, false, 0, 0);
  if (size_from_first_image) {
    camera_.camera.width = first.cols;
    camera_.camera.height = first.rows;
    camera_.camera.fx = camera_.camera.fy = first.cols;
    camera_.camera.cx = (first.cols - 1) / 2.0;
    camera_.camera.cy = (first.rows - 1) / 2.0;
    if (options.h0) camera_.h0 = *options.h0;
  }
  if (first.cols != camera_.camera.width || first.rows != camera_.camera.height) {
    ThrowFileError(first_path, "image is " + SizeText(first.cols, first.rows) + " but " +
                                   options.camera_yaml + " says " +
                                   SizeText(camera_.camera.width, camera_.camera.height));
  }
  UndistortWithCamerasLens();

  const std::vector<double> times =
      TimestampsFor((fs::path(folder_) / "times.txt").string(), total_images_, &notes_);
  const auto [begin, end] = SelectRange(options.frames, total_images_, folder_, &notes_);
  first_index_ = begin;
  for (size_t i = begin; i < end; ++i) {
    paths_.push_back((fs::path(folder_) / names[i]).string());
    timestamps_.push_back(times[i]);
  }
}

std::string ImageFolder::Describe() const {
  return "image folder " + folder_ + " (" + DescribeRange(first_index_, paths_.size()) + " of " +
         std::to_string(total_images_) + ")";
}

// ---------------------------------------------------------------------------------------

VideoFile::VideoFile(const FrameSourceOptions& options) : path_(options.input) {
  options.Check();
  CheckInputFile(path_, "video file");
  camera_ = ReadCameraForInput(options, "a video");
  if (!camera_.distortion.empty()) undistorter_.emplace(camera_.camera, camera_.distortion);
  color_ = options.color;
  if (!capture_.Open(path_)) {
    ThrowFileError(path_, "cannot open video (unsupported container or codec, or not a video)");
  }

  const int width = static_cast<int>(capture_.Get(cv::CAP_PROP_FRAME_WIDTH));
  const int height = static_cast<int>(capture_.Get(cv::CAP_PROP_FRAME_HEIGHT));
  if (width > 0 && height > 0 &&
      (width != camera_.camera.width || height != camera_.camera.height)) {
    ThrowFileError(path_, "video frames are " + SizeText(width, height) + " but " +
                              options.camera_yaml + " says " +
                              SizeText(camera_.camera.width, camera_.camera.height));
  }

  const double fps = capture_.Get(cv::CAP_PROP_FPS);
  if (std::isfinite(fps) && fps > 0.0) {
    fps_ = fps;
  } else {
    char rate[32];
    std::snprintf(rate, sizeof(rate), "%g", kDefaultFrameRateHz);
    notes_.push_back(path_ + " reports no frame rate: assuming " + rate +
                     " Hz where it has no timestamps");
  }

  const double count = capture_.Get(cv::CAP_PROP_FRAME_COUNT);
  range_ = options.frames;
  if (std::isfinite(count) && count > 0.0) {
    const auto [begin, end] =
        SelectRange(options.frames, static_cast<size_t>(count), path_, &notes_);
    range_.end = std::min(range_.end, end);
    size_ = end - begin;
  } else {
    notes_.push_back(path_ + " does not report its frame count: size() is 0 and reading " +
                     "goes on until the video ends");
  }
}

bool VideoFile::Next(Frame* frame) {
  while (next_index_ < range_.begin) {
    if (!capture_.Grab()) {
      ThrowFileError(path_, "the video ended at frame " + std::to_string(next_index_) +
                                ", before the first selected frame " +
                                std::to_string(range_.begin));
    }
    ++next_index_;
  }
  if (next_index_ >= range_.end || !capture_.Grab()) return false;
  const size_t index = next_index_++;
  const std::string frame_path = path_ + "#" + std::to_string(index);

  // The container's time is the truth when the backend provides it (variable frame rate);
  // some backends report 0 or stale values, so accept it only while it increases.
  const double msec = capture_.Get(cv::CAP_PROP_POS_MSEC);
  double timestamp = static_cast<double>(index) / fps_;
  if (std::isfinite(msec) && msec >= 0.0 &&
      (index == range_.begin || msec / 1000.0 > last_timestamp_)) {
    timestamp = msec / 1000.0;
  }

  cv::Mat decoded;
  if (!capture_.Retrieve(&decoded) || decoded.empty()) {
    ThrowFileError(frame_path, "cannot decode video frame");
  }
  if (decoded.cols != camera_.camera.width || decoded.rows != camera_.camera.height) {
    ThrowFileError(frame_path, "frame is " + SizeText(decoded.cols, decoded.rows) +
                                   " but the camera is " +
                                   SizeText(camera_.camera.width, camera_.camera.height));
  }
  frame->image = cv::Mat();
  if (decoded.channels() == 1) {
    if (color_) {
      cv::cvtColor(decoded, frame->image, cv::COLOR_GRAY2BGR);
    } else {
      frame->image = decoded;
    }
  } else if (decoded.channels() == 3) {
    if (color_) {
      frame->image = decoded;
    } else {
      cv::cvtColor(decoded, frame->image, cv::COLOR_BGR2GRAY);
    }
  } else {
    ThrowFileError(frame_path,
                   "unexpected " + std::to_string(decoded.channels()) + "-channel video frame");
  }
  if (frame->image.depth() != CV_8U) ThrowFileError(frame_path, "video frame is not 8-bit");
  if (undistorter_) frame->image = undistorter_->Undistort(frame->image);
  frame->index = index;
  frame->timestamp = timestamp;
  frame->path = frame_path;
  last_timestamp_ = timestamp;
  return true;
}

std::string VideoFile::Describe() const {
  std::string text = "video " + path_ + " (";
  if (size_ > 0) {
    text += DescribeRange(range_.begin, size_);
  } else {
    text += "frames " + FormatFrameRange(range_) + ", count unknown";
  }
  char rate[32];
  std::snprintf(rate, sizeof(rate), ", %.3g fps)", fps_);
  return text + rate;
}

// ---------------------------------------------------------------------------------------

std::unique_ptr<FrameSource> OpenFrameSource(const FrameSourceOptions& options) {
  options.Check();
  const FrameSourceType type =
      options.type == FrameSourceType::kAuto ? DetectFrameSourceType(options.input) : options.type;
  switch (type) {
    case FrameSourceType::kKitti:
      return std::make_unique<KittiSequence>(options);
    case FrameSourceType::kImageFolder:
      return std::make_unique<ImageFolder>(options);
    case FrameSourceType::kVideo:
      return std::make_unique<VideoFile>(options);
    case FrameSourceType::kAuto:
      break;
  }
  throw Error("internal: unresolved input type");
}

}  // namespace roadscale
