// The `roadscale` Python module: roadscale::Odometry for a program that has its frames as
// numpy arrays. Built when pybind11 and Python's headers are there (scripts/setup.sh installs
// them); README, "Use it as a library".
#include <cstdint>
#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "roadscale/config/config_yaml.h"
#include "roadscale/config/rescale_config.h"
#include "roadscale/eval/metrics_json.h"
#include "roadscale/eval/trajectory_evaluation.h"
#include "roadscale/io/camera_setup.h"
#include "roadscale/odometry/odometry.h"
#include "roadscale/odometry/odometry_config.h"
#include "roadscale/rescale/trajectory_rescaler.h"
#include "roadscale/util/error.h"

namespace py = pybind11;

namespace roadscale {
namespace {

CameraSetup CameraFrom(const py::object& camera) {
  if (py::isinstance<py::str>(camera)) return ReadCameraYaml(camera.cast<std::string>());
  if (!py::isinstance<py::dict>(camera)) {
    throw Error("camera: give a camera YAML's path or a dict of fx, fy, cx, cy, width, height, h0");
  }
  const py::dict values = camera.cast<py::dict>();
  const auto value = [&](const char* key) {
    if (!values.contains(key)) throw Error(std::string("camera: no '") + key + "'");
    return values[key];
  };
  CameraSetup setup;
  setup.camera.fx = value("fx").cast<double>();
  setup.camera.fy = value("fy").cast<double>();
  setup.camera.cx = value("cx").cast<double>();
  setup.camera.cy = value("cy").cast<double>();
  setup.camera.width = value("width").cast<int>();
  setup.camera.height = value("height").cast<int>();
  setup.h0 = value("h0").cast<double>();
  setup.Check();
  return setup;
}

py::array_t<double> PoseMatrix(const Rigid3d& world_from_cam) {
  py::array_t<double> pose({4, 4});
  auto cells = pose.mutable_unchecked<2>();
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) cells(row, col) = world_from_cam.matrix()(row, col);
  }
  return pose;
}

// A finished frame as Python sees it.
py::dict FrameDict(const FrameRecord& record, const Rigid3d& world_from_cam) {
  py::dict frame;
  frame["index"] = record.index;
  frame["timestamp"] = record.timestamp;
  frame["status"] = record.status;
  frame["step_length_m"] = record.step_length_m;
  frame["keyframe"] = record.keyframe;
  frame["world_from_cam"] = PoseMatrix(world_from_cam);
  return frame;
}

// Poses as an (N, 4, 4) or (N, 3, 4) array of world_from_cam.
std::vector<Rigid3d> PosesFrom(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& poses, const char* name) {
  if (poses.ndim() != 3 || poses.shape(2) != 4 || (poses.shape(1) != 3 && poses.shape(1) != 4)) {
    throw Error(std::string(name) + ": give an (N, 4, 4) or (N, 3, 4) array of poses");
  }
  const auto cells = poses.unchecked<3>();
  std::vector<Rigid3d> out;
  for (py::ssize_t k = 0; k < poses.shape(0); ++k) {
    Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 4; ++col) matrix(row, col) = cells(k, row, col);
    }
    Rigid3d pose;
    pose.matrix() = matrix;
    out.push_back(pose);
  }
  return out;
}

// `roadscale eval --json`'s dict for paired poses.
py::object Evaluate(const py::array_t<double, py::array::c_style | py::array::forcecast>& gt,
                    const py::array_t<double, py::array::c_style | py::array::forcecast>& est) {
  const TrajectoryEvaluation evaluation =
      EvaluateTrajectory(PosesFrom(gt, "gt"), PosesFrom(est, "est"));
  return py::module_::import("json").attr("loads")(FormatMetricsJson(evaluation));
}

py::array_t<double> PoseArray(const std::vector<Rigid3d>& poses) {
  py::array_t<double> array(
      {static_cast<py::ssize_t>(poses.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto cells = array.mutable_unchecked<3>();
  for (size_t k = 0; k < poses.size(); ++k) {
    for (int row = 0; row < 4; ++row) {
      for (int col = 0; col < 4; ++col) cells(k, row, col) = poses[k].matrix()(row, col);
    }
  }
  return array;
}

// An image handed in from Python, without a copy.
cv::Mat ImageView(const py::array_t<std::uint8_t, py::array::c_style>& image, const char* what) {
  if (image.ndim() != 2 && !(image.ndim() == 3 && image.shape(2) == 3)) {
    throw Error(std::string(what) + ": the image must be H x W (grey) or H x W x 3 (BGR), uint8");
  }
  return cv::Mat(static_cast<int>(image.shape(0)), static_cast<int>(image.shape(1)),
                 image.ndim() == 2 ? CV_8UC1 : CV_8UC3, const_cast<std::uint8_t*>(image.data()));
}

// The segmenter `roadscale rescale` opens: label PNGs (named like the frames), else a model
// YAML (one copy: rescale segments the pose frames in turn), else none.
std::unique_ptr<Segmenter> RescaleSegmenter(const std::string& labels, const std::string& model) {
  RunConfig config;
  config.labels = labels;
  config.segmentation.model = model.empty() ? "none" : model;
  config.segmentation.workers = 1;
  std::vector<std::unique_ptr<Segmenter>> segmenters = MakeConfigSegmenters(config);
  return segmenters.empty() ? nullptr : std::move(segmenters.front());
}

// `roadscale rescale` on arrays: another VO's poses and the frames they were made from.
py::dict Rescale(const py::array_t<double, py::array::c_style | py::array::forcecast>& poses,
                 const py::iterable& images, const py::object& camera,
                 const std::string& config_path, const std::string& labels,
                 const std::string& model, const std::optional<std::vector<size_t>>& pose_frames,
                 const std::optional<std::vector<double>>& timestamps) {
  const CameraSetup setup = CameraFrom(camera);
  TrajectoryRescalerOptions options = RescalerOptionsFromConfig(config_path);
  options.scale.camera_height = setup.h0;
  Trajectory external;
  external.world_from_cam = PosesFrom(poses, "poses");
  std::vector<size_t> frames_of_poses;
  if (pose_frames) {
    frames_of_poses = *pose_frames;
  } else {
    for (size_t k = 0; k < external.size(); ++k) frames_of_poses.push_back(k);
  }
  TrajectoryRescaler rescaler(setup.camera, external, frames_of_poses, options);
  if (timestamps && timestamps->size() <= rescaler.last_frame()) {
    throw Error("rescale: " + std::to_string(timestamps->size()) +
                " timestamps, but the last pose is at frame " +
                std::to_string(rescaler.last_frame()));
  }
  std::unique_ptr<Segmenter> segmenter = RescaleSegmenter(labels, model);

  std::vector<Rigid3d> metric;
  py::list statuses;
  py::list ratios;
  const auto take = [&](const std::vector<RescaledPose>& finished) {
    for (const RescaledPose& pose : finished) {
      metric.push_back(pose.world_from_cam);
      statuses.append(RescaleStatusName(pose.status));
      ratios.append(pose.ratio);
    }
  };
  const SegmentationResult no_segmentation;
  size_t position = 0;
  for (const py::handle item : images) {
    if (position > rescaler.last_frame()) break;
    if (position >= rescaler.first_frame()) {
      // The array must outlive the view; the rescaler keeps the frame's image, so it gets a copy.
      const auto array = item.cast<py::array_t<std::uint8_t, py::array::c_style>>();
      const cv::Mat image = ImageView(array, "rescale");
      Frame frame;
      frame.index = position;
      frame.timestamp = timestamps ? (*timestamps)[position]
                                   : static_cast<double>(position) / kDefaultFrameRateHz;
      char name[32];
      std::snprintf(name, sizeof(name), "%06zu", position);
      frame.path = name;
      SegmentationResult segmentation;
      std::vector<RescaledPose> finished;
      {
        const py::gil_scoped_release release;
        if (image.channels() == 3) {
          cv::cvtColor(image, frame.image, cv::COLOR_BGR2GRAY);
        } else {
          frame.image = image.clone();
        }
        if (segmenter && rescaler.IsPoseFrame(position)) {
          segmentation = segmenter->Segment(image, name);
        }
        finished = rescaler.AddFrame(frame, segmenter ? segmentation : no_segmentation);
      }
      take(finished);
    }
    ++position;
  }
  if (position <= rescaler.last_frame()) {
    throw Error("rescale: the last pose is at frame " + std::to_string(rescaler.last_frame()) +
                " but only " + std::to_string(position) + " images came");
  }
  take(rescaler.Finish());
  py::dict result;
  result["poses"] = PoseArray(metric);
  result["status"] = statuses;
  result["ratio"] = ratios;
  return result;
}

class PythonOdometry {
 public:
  PythonOdometry(const py::object& camera, const std::string& config_path,
                 const std::string& labels, const std::string& model, bool threaded) {
    RunConfig config;
    if (!config_path.empty()) ReadRunConfig(config_path, &config);
    // "default" names the command line's shared network, which a module cannot find.
    if (config.segmentation.model == "default") config.segmentation.model = "none";
    if (!model.empty()) config.segmentation.model = model;
    if (!labels.empty()) config.labels = labels;
    OdometryOptions options = OdometryOptionsFromConfig(config, CameraFrom(camera));
    options.run.threaded = threaded;
    segmenters_ = MakeConfigSegmenters(config);
    odometry_ = std::make_unique<Odometry>(
        options, Pointers(segmenters_),
        [this](const FrameRecord& record, const Rigid3d& pose) {
          const std::lock_guard<std::mutex> lock(mutex_);
          finished_.emplace_back(record, pose);
        },
        /*scale=*/nullptr,
        [this](const ProvisionalPose& pose) {
          const std::lock_guard<std::mutex> lock(mutex_);
          latest_ = pose;
        });
  }

  py::list Track(const py::array_t<std::uint8_t, py::array::c_style>& image, double timestamp,
                 const std::string& name) {
    const cv::Mat view = ImageView(image, "track");
    {
      const py::gil_scoped_release release;
      odometry_->Track(view, timestamp, name);
    }
    return TakeFinished();
  }

  py::list Finish() {
    {
      const py::gil_scoped_release release;
      summary_ = odometry_->Finish().summary.Format();
    }
    return TakeFinished();
  }

  const std::string& summary() const { return summary_; }

  py::object Latest() {
    std::optional<ProvisionalPose> latest;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      latest = latest_;
    }
    if (!latest) return py::none();
    py::dict pose;
    pose["index"] = latest->index;
    pose["timestamp"] = latest->timestamp;
    pose["world_from_cam"] = PoseMatrix(latest->world_from_cam);
    pose["metric"] = latest->metric;
    return pose;
  }

  py::array_t<double> Poses() const { return PoseArray(all_poses_); }

 private:
  py::list TakeFinished() {
    std::vector<std::pair<FrameRecord, Rigid3d>> finished;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      finished.swap(finished_);
    }
    py::list frames;
    for (const auto& [record, pose] : finished) {
      frames.append(FrameDict(record, pose));
      all_poses_.push_back(pose);
    }
    return frames;
  }

  std::vector<std::unique_ptr<Segmenter>> segmenters_;
  std::mutex mutex_;
  std::vector<std::pair<FrameRecord, Rigid3d>> finished_;
  std::optional<ProvisionalPose> latest_;
  std::string summary_;
  std::vector<Rigid3d> all_poses_;  // every frame handed to Python so far, in order
  // Last: its threads stop before the members they write to go.
  std::unique_ptr<Odometry> odometry_;
};

}  // namespace
}  // namespace roadscale

PYBIND11_MODULE(roadscale, module) {
  using roadscale::PythonOdometry;
  module.doc() =
      "roadscale: metric monocular visual odometry, scaled by the road and the "
      "camera's height above it.";
  py::register_exception<roadscale::Error>(module, "Error", PyExc_RuntimeError);
  py::class_<PythonOdometry>(module, "Odometry", R"doc(
Monocular images in, metric poses out, as `roadscale run` gives them for the same frames.

camera:   a camera YAML's path (Camera: fx fy cx cy width height h0; a run's config_used.yaml
          works) or a dict with those keys; h0 is the camera's height above the road, metres.
config:   a run config YAML (config/kitti.yaml lists its keys); "" for the defaults.
labels:   a folder of label PNGs named like the frames (track's `name`), Cityscapes train ids.
model:    a segmentation model YAML (config/models/); neither it nor labels: no segmentation.
threaded: segmentation, frontend, scale and pose on their own threads (the same poses).
)doc")
      .def(py::init<const py::object&, const std::string&, const std::string&, const std::string&,
                    bool>(),
           py::arg("camera"), py::arg("config") = "", py::arg("labels") = "", py::arg("model") = "",
           py::arg("threaded") = true)
      .def("track", &PythonOdometry::Track, py::arg("image"), py::arg("timestamp"),
           py::arg("name") = "",
           "Hands in the next frame (uint8, H x W grey or H x W x 3 BGR; timestamps in seconds, "
           "increasing; `name` the image file for label PNGs). Returns the frames whose poses "
           "became final since the last call: dicts of index, timestamp, status, "
           "step_length_m, keyframe and world_from_cam (4 x 4, metres; frame 0 is the world).")
      .def("finish", &PythonOdometry::Finish,
           "Processes what is left and returns the last finished frames.")
      .def_property_readonly("summary", &PythonOdometry::summary,
                             "The run's summary once finish() has returned.")
      .def("latest", &PythonOdometry::Latest,
           "The newest frame's provisional pose, None before the first: a dict of index, "
           "timestamp, world_from_cam (4 x 4) and metric (False before the first scale: "
           "map units). The map's localisation as soon as the odometry took the frame (it runs "
           "up to two frames behind track()); the window refines it into the final pose.")
      .def("poses", &PythonOdometry::Poses,
           "The world_from_cam of every frame returned so far, as an (N, 4, 4) array.");
  module.def("rescale", &roadscale::Rescale, py::arg("poses"), py::arg("images"), py::arg("camera"),
             py::arg("config") = "", py::arg("labels") = "", py::arg("model") = "",
             py::arg("pose_frames") = py::none(), py::arg("timestamps") = py::none(), R"doc(
Another VO's trajectory given its metric scale from the road, as `roadscale rescale` does.

poses:       the VO's world_from_cam, an (N, 4, 4) or (N, 3, 4) array (any scale).
images:      the frames, in order, as uint8 arrays (H x W grey or H x W x 3 BGR); any iterable,
             read up to the last pose's frame.
camera:      a camera YAML's path or a dict of fx, fy, cx, cy, width, height, h0.
config:      a run config YAML (its Scale and Mapping blocks), "" for rescale's defaults.
labels:      a folder of label PNGs named 000000.png, ... by frame; or model: a model YAML.
pose_frames: the frame of each pose (increasing); default pose i at frame i.
timestamps:  seconds of each frame; default frame / 10.
Returns a dict: poses (N, 4, 4) in metres, status and ratio (metres per VO unit) per pose.
)doc");
  module.def("evaluate", &roadscale::Evaluate, py::arg("gt"), py::arg("est"),
             "The KITTI devkit metric, ATE, RPE and length ratio of paired poses ((N, 4, 4) or "
             "(N, 3, 4) arrays of world_from_cam), as `roadscale eval --json` gives them.");
}
