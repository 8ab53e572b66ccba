#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "roadscale/io/camera_setup.h"
#include "roadscale/io/image_codecs.h"
#include "roadscale/io/image_undistorter.h"
#include "roadscale/io/trajectory_io.h"

namespace roadscale {

// One input image. Frames are loaded one at a time and owned by the caller: a source never
// keeps more than the frame it is decoding, so a 4,500-frame sequence runs in the memory
// of one image.
struct Frame {
  // Frame number in the whole input (the KITTI file number, the video frame number), not
  // the position inside a selected range: `--frames 100:200` delivers indexes 100..199.
  size_t index = 0;
  // Seconds (times.txt, the video's timestamps, or index / kDefaultFrameRateHz).
  double timestamp = 0.0;
  // CV_8UC1 grey by default, CV_8UC3 BGR when FrameSourceOptions::color is set.
  cv::Mat image;
  // The image file, or "VIDEO#INDEX" for a video frame (used in messages).
  std::string path;
};

// Frame rate assumed when an input has no timestamps (KITTI's 10 Hz).
inline constexpr double kDefaultFrameRateHz = 10.0;

// A half-open range [begin, end) of frame indexes.
struct FrameRange {
  static constexpr size_t kToEnd = std::numeric_limits<size_t>::max();
  size_t begin = 0;
  size_t end = kToEnd;

  bool IsAll() const { return begin == 0 && end == kToEnd; }
};

// Parses the CLI's `--frames` value: "A:B" (frames A..B-1), "A:" (A to the end), ":B"
// (0..B-1) or "" / ":" (all). Throws Error unless A < B and both are non-negative integers.
FrameRange ParseFrameRange(const std::string& text);
// "A:B" / "A:" / ":" for messages.
std::string FormatFrameRange(const FrameRange& range);

enum class FrameSourceType {
  kAuto,         // a file is a video; a folder with image_0/ or image_2/ is a KITTI sequence;
                 // any other folder is an image folder
  kKitti,        // KittiSequence
  kImageFolder,  // ImageFolder
  kVideo,        // VideoFile
};

// "auto", "kitti", "images" or "video"; throws Error otherwise.
FrameSourceType ParseFrameSourceType(const std::string& name);
// Resolves kAuto for `input` as described above; throws Error when `input` does not exist.
FrameSourceType DetectFrameSourceType(const std::string& input);

struct FrameSourceOptions {
  // KITTI sequence folder (.../sequences/NN), image folder, or video file.
  std::string input;
  FrameSourceType type = FrameSourceType::kAuto;
  // Camera YAML (see ReadCameraYaml; a project config file works). Required for an image
  // folder or a video. For a KITTI sequence the intrinsics come from calib.txt and only this
  // file's h0 is used (a note says so when its intrinsics differ from calib.txt's).
  std::string camera_yaml;
  // KITTI camera N in 0..3 reads image_N/ with the intrinsics of P_N (0 grey left, 2 colour
  // left); -1 picks image_0 when the sequence has it, else image_2.
  int kitti_camera = -1;
  // Deliver BGR images instead of grey (a grey input is then repeated over 3 channels).
  bool color = false;
  // Camera height above the road in metres. When set it replaces the camera YAML's h0. For a
  // KITTI sequence (calib.txt has no height) see KittiSequence for where h0 comes from.
  std::optional<double> h0;
  // Which frames to deliver. An end beyond the last frame is clamped (with a note); a begin
  // at or beyond it throws Error.
  FrameRange frames;
  // For commands that need the image size only (segment): an image folder without
  // camera_yaml takes its size from its first image, with nominal intrinsics (fx = fy =
  // width, principal point at the centre) that nothing may use for geometry.
  bool image_size_only = false;

  // Throws Error on an empty input, an unknown kitti_camera, a non-positive h0, or an
  // empty frame range.
  void Check() const;
};

// The interface every input goes through.
//
// Reading is sequential (Next), because that is what a video allows: OpenCV's seeking is
// frame-accurate for few codecs. Image-file sources (KittiSequence, ImageFolder) also offer
// random access through ImageFileSequence::Read. A source is not thread-safe; the pipeline
// reads it from one thread.
class FrameSource {
 public:
  virtual ~FrameSource() = default;

  // Intrinsics, image size and camera height; every delivered image has this size.
  virtual const CameraSetup& camera() const = 0;

  // Number of frames in the selected range. Exact for image files; for a video it comes
  // from the frame count OpenCV reports, which some containers only estimate: Next() is
  // the authority on where a video ends.
  virtual size_t size() const = 0;

  // Decodes the next frame of the selected range into `*frame`; false after the last one.
  // Throws Error naming the file (and frame) when an image cannot be decoded or its size
  // differs from camera()'s.
  virtual bool Next(Frame* frame) = 0;

  // Ground-truth world_from_cam of the delivered frames, in order (the i-th pose belongs to
  // the i-th frame Next() delivers), with their timestamps; nullptr when the input has
  // none. Poses are as in the file: the world is camera 0 at frame 0 of the whole input.
  virtual const Trajectory* ground_truth() const { return nullptr; }

  // Things the user should know that are not errors (rows of times.txt or poses beyond the
  // last image, an assumed frame rate, a clamped range), one sentence each.
  virtual std::vector<std::string> notes() const { return {}; }

  // One line for logs, e.g. "KITTI sequence /data/sequences/00 (image_0, frames 0:200)".
  virtual std::string Describe() const = 0;
};

// A source backed by one image file per frame, with random access.
class ImageFileSequence : public FrameSource {
 public:
  const CameraSetup& camera() const override { return camera_; }
  size_t size() const override { return paths_.size(); }
  bool Next(Frame* frame) override;
  std::vector<std::string> notes() const override { return notes_; }

  // The frame at `position` (0 .. size()-1) of the selected range, whatever Next() has
  // delivered. Throws Error when `position` is out of range or the image is unreadable.
  // Read() changes nothing, so several threads may call it at once (prefetching).
  Frame Read(size_t position) const;

  // Paths of the selected frames' images, in order.
  const std::vector<std::string>& image_paths() const { return paths_; }
  // Timestamps of the selected frames (seconds), in order, known before any image is read:
  // another program's trajectory is associated with the frames by them.
  const std::vector<double>& timestamps() const { return timestamps_; }

 protected:
  ImageFileSequence() = default;

  // After camera_ is set: undistort every image Read() returns when the camera has a lens
  // distortion.
  void UndistortWithCamerasLens();

  CameraSetup camera_;
  std::vector<std::string> paths_;  // selected frames only
  std::vector<double> timestamps_;  // one per selected frame
  size_t first_index_ = 0;          // Frame::index of paths_[0]
  bool color_ = false;
  std::vector<std::string> notes_;

 private:
  size_t next_position_ = 0;
  std::shared_ptr<const ImageUndistorter> undistorter_;  // null for a pinhole camera
};

// A KITTI odometry sequence folder `.../sequences/NN`:
//   image_0/ or image_2/  %06d.png, numbered 000000 upwards without gaps
//   calib.txt             P0 (image_0) or P2 (image_2) gives the intrinsics; the image size
//                         comes from the first image
//   camera.yaml           optional (roadscale's synthetic scenes write it): its h0 and lens
//                         distortion are used
// h0 is the first of: options.h0, the h0 of options.camera_yaml, the sequence's camera.yaml,
// KITTI's documented 1.65 m (with a note, as the scale depends on it).
//   times.txt             optional; without it timestamps are index / kDefaultFrameRateHz
//   ../../poses/NN.txt    optional ground truth
// The images define the sequence. times.txt and the poses may have MORE rows than there are
// images (a partial download, such as the shared 200-frame copy of sequence 00 next to the
// full 4,541-row files): the first rows pair with the images, the rest are ignored, and a
// note says so. FEWER rows than images is an error naming the file.
class KittiSequence : public ImageFileSequence {
 public:
  // Uses options.input (the sequence folder), kitti_camera, color, h0, camera_yaml (for h0
  // only) and frames. Throws
  // Error naming the file or folder (and line) on a missing folder, no images, a gap in the
  // numbering (naming the first missing file), a malformed calib.txt, times.txt or poses
  // file, or one shorter than the images.
  explicit KittiSequence(const FrameSourceOptions& options);

  const Trajectory* ground_truth() const override {
    return ground_truth_ ? &*ground_truth_ : nullptr;
  }
  std::string Describe() const override;

  // The camera actually used (0 or 2).
  int kitti_camera() const { return kitti_camera_; }

 private:
  std::string sequence_dir_;
  int kitti_camera_ = 0;
  size_t total_images_ = 0;
  std::optional<Trajectory> ground_truth_;
};

// A folder of images (*.png, *.jpg, *.jpeg, any case) plus a camera YAML. Images are sorted
// by name with digit runs compared as numbers ("img9" before "img10"). When every name
// (without extension) is a number, the numbers must be consecutive: a gap means a dropped
// frame, and the error names the first missing file. Timestamps come from the folder's
// times.txt when it exists (same rules as KITTI: at least one row per image), else
// index / kDefaultFrameRateHz (a note says so). Frame::index is the position in this order
// (0 for the first image, whatever its name).
class ImageFolder : public ImageFileSequence {
 public:
  // Uses options.input (the folder), camera_yaml (required unless image_size_only), color,
  // h0 and frames. Throws
  // Error on a missing folder or camera YAML, no images, a gap in the numbering, a short
  // times.txt, or a first image whose size differs from the YAML's width and height.
  explicit ImageFolder(const FrameSourceOptions& options);

  std::string Describe() const override;

 private:
  std::string folder_;
  size_t total_images_ = 0;
};

// A video file read with cv::VideoCapture (VideoReader), plus a camera YAML. Timestamps come from
// the container (CAP_PROP_POS_MSEC) when it has them, else index / fps (CAP_PROP_FPS), else index /
// kDefaultFrameRateHz. A range's first frames are skipped by decoding, not seeking, so that
// Frame::index is exact.
class VideoFile : public FrameSource {
 public:
  // Uses options.input (the video), camera_yaml (required), color, h0 and frames. Throws
  // Error when the video cannot be opened or its frame size differs from the YAML's.
  explicit VideoFile(const FrameSourceOptions& options);

  const CameraSetup& camera() const override { return camera_; }
  size_t size() const override { return size_; }
  bool Next(Frame* frame) override;
  std::vector<std::string> notes() const override { return notes_; }
  std::string Describe() const override;

 private:
  std::string path_;
  CameraSetup camera_;
  VideoReader capture_;
  FrameRange range_;
  size_t size_ = 0;
  size_t next_index_ = 0;  // index of the frame the next grab() returns
  double last_timestamp_ = 0.0;
  double fps_ = kDefaultFrameRateHz;
  bool color_ = false;
  std::vector<std::string> notes_;
  std::optional<ImageUndistorter> undistorter_;  // empty for a pinhole camera
};

// The factory the CLI uses: checks the options, resolves kAuto, and opens the source.
std::unique_ptr<FrameSource> OpenFrameSource(const FrameSourceOptions& options);

}  // namespace roadscale
