#include "roadscale/batch/manifest.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include "roadscale/frontend/feature_detector.h"
#include "roadscale/geometry/camera_height.h"
#include "roadscale/io/frame_source.h"
#include "roadscale/util/error.h"
#include "roadscale/util/yaml_file.h"

namespace roadscale::batch {
namespace {

namespace fs = std::filesystem;

enum class PathKind { kFolder, kFile };

// `value` relative to the manifest's folder, absolute and without "." or "..".
std::string Resolve(const fs::path& base, const std::string& value) {
  return fs::absolute(base / value).lexically_normal().string();
}

// Reads one key of a drive; throws Error naming the manifest and the value's line.
class DriveReader {
 public:
  DriveReader(const std::string& manifest, const YAML::Node& node, BatchDrive* drive)
      : manifest_(manifest), base_(fs::path(manifest).parent_path()), drive_(drive) {
    const std::map<std::string, std::function<void(const YAML::Node&)>> readers = {
        {"name", [this](const YAML::Node& v) { drive_->name = Text(v); }},
        {"kitti", [this](const YAML::Node& v) { drive_->kitti = Path(v, PathKind::kFolder); }},
        {"images", [this](const YAML::Node& v) { drive_->images = Path(v, PathKind::kFolder); }},
        {"video", [this](const YAML::Node& v) { drive_->video = Path(v, PathKind::kFile); }},
        {"camera", [this](const YAML::Node& v) { drive_->camera = Path(v, PathKind::kFile); }},
        {"config", [this](const YAML::Node& v) { drive_->config = Path(v, PathKind::kFile); }},
        {"model", [this](const YAML::Node& v) { drive_->model = Path(v, PathKind::kFile); }},
        {"labels", [this](const YAML::Node& v) { drive_->labels = Path(v, PathKind::kFolder); }},
        {"no_segmentation", [this](const YAML::Node& v) { drive_->no_segmentation = Flag(v); }},
        {"scale", [this](const YAML::Node& v) { drive_->scale = Scale(v); }},
        {"detector", [this](const YAML::Node& v) { drive_->detector = Detector(v); }},
        {"h0", [this](const YAML::Node& v) { drive_->h0 = H0(v); }},
        {"frames", [this](const YAML::Node& v) { drive_->frames = Frames(v); }},
        {"sequential", [this](const YAML::Node& v) { drive_->sequential = Flag(v); }},
    };
    if (!node.IsMap()) Fail(node, "expected a drive: a mapping with name: and an input");
    for (const auto& entry : node) {
      const std::string key = entry.first.as<std::string>();
      const auto reader = readers.find(key);
      if (reader == readers.end()) {
        std::string names;
        for (const auto& known : readers) names += (names.empty() ? "" : ", ") + known.first;
        Fail(entry.first, "unknown key '" + key + "' (expected one of " + names + ")");
      }
      key_ = key;
      if (entry.second.IsNull()) Fail(entry.second, key + " has no value");
      reader->second(entry.second);
    }
    key_.clear();
    if (drive_->name.empty()) Fail(node, "a drive without name:");
    const std::string what = "drive '" + drive_->name + "'";
    try {
      CheckDriveName(drive_->name, what);
    } catch (const Error& error) {
      Fail(node["name"], error.what());
    }
    const int inputs = !drive_->kitti.empty() + !drive_->images.empty() + !drive_->video.empty();
    if (inputs != 1) Fail(node, what + ": give exactly one of kitti, images, video");
    if (!drive_->model.empty() + !drive_->labels.empty() + drive_->no_segmentation > 1) {
      Fail(node, what + ": give at most one of model, labels, no_segmentation");
    }
    if (drive_->kitti.empty() && drive_->camera.empty() && drive_->config.empty()) {
      Fail(node, what + ": images and video need camera: (or a config: with a Camera: block)");
    }
  }

 private:
  [[noreturn]] void Fail(const YAML::Node& node, const std::string& message) const {
    ThrowFileError(manifest_, YamlLine(node.Mark()), message);
  }

  std::string Text(const YAML::Node& value) const {
    if (!value.IsScalar()) Fail(value, key_ + ": expected a single value");
    return value.as<std::string>();
  }

  std::string Path(const YAML::Node& value, PathKind kind) const {
    const std::string path = Resolve(base_, Text(value));
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    const char* noun = kind == PathKind::kFolder ? "folder" : "file";
    if (!fs::exists(status)) Fail(value, key_ + " " + noun + " '" + path + "' does not exist");
    if (kind == PathKind::kFolder && !fs::is_directory(status)) {
      Fail(value, key_ + " '" + path + "' is not a folder");
    }
    if (kind == PathKind::kFile && fs::is_directory(status)) {
      Fail(value, key_ + " '" + path + "' is a folder, expected a file");
    }
    return path;
  }

  bool Flag(const YAML::Node& value) const {
    bool flag = false;
    if (!value.IsScalar() || !YAML::convert<bool>::decode(value, flag)) {
      Fail(value, key_ + ": expected true or false");
    }
    return flag;
  }

  std::string Scale(const YAML::Node& value) const {
    const std::string scale = Text(value);
    if (scale != "road" && scale != "oracle") {
      Fail(value, "unknown scale '" + scale + "' (expected road or oracle)");
    }
    return scale;
  }

  std::string Detector(const YAML::Node& value) const {
    const std::string detector = Text(value);
    try {
      ParseDetectorType(detector);
    } catch (const Error& error) {
      Fail(value, error.what());
    }
    return detector;
  }

  double H0(const YAML::Node& value) const {
    double h0 = 0.0;
    if (!value.IsScalar() || !YAML::convert<double>::decode(value, h0) ||
        !(h0 >= kMinCameraHeightM) || h0 > kMaxCameraHeightM) {
      char text[80];
      std::snprintf(text, sizeof(text), "h0: expected a camera height in metres in [%g, %g]",
                    kMinCameraHeightM, kMaxCameraHeightM);
      Fail(value, text);
    }
    return h0;
  }

  std::string Frames(const YAML::Node& value) const {
    const std::string frames = Text(value);
    try {
      ParseFrameRange(frames);
    } catch (const Error& error) {
      Fail(value, error.what());
    }
    return frames;
  }

  std::string manifest_;
  fs::path base_;
  BatchDrive* drive_;
  std::string key_;  // the key being read, for messages
};

}  // namespace

void CheckDriveName(const std::string& name, const std::string& what) {
  const bool plain = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_' || c == '-';
  });
  if (name.empty() || !plain || name.front() == '.' || name.size() > 100) {
    throw Error(what +
                ": a drive's name must be a folder name of letters, digits, '.', '_' and "
                "'-' (not starting with '.', at most 100 characters)");
  }
  // The batch's own files beside the drives' folders; compared without case, as a
  // case-insensitive file system (macOS, Windows shares) would.
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "slurm") throw Error(what + ": 'slurm' is the folder of the Slurm scripts");
  for (const char* reserved :
       {"batch.json", "summary.md", "summary.csv", "summary.json", "summary.html"}) {
    if (lower == reserved) {
      throw Error(what + ": '" + reserved +
                  "' is a file of the batch itself (its list of "
                  "drives or its summary)");
    }
  }
}

BatchManifest ReadBatchManifest(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path, "batch manifest");
  if (!root.IsMap()) {
    ThrowFileError(path, root.IsNull() ? 0 : YamlLine(root.Mark()),
                   "expected a mapping with drives: (a list of drives)");
  }
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    if (key != "drives") {
      ThrowFileError(path, YamlLine(entry.first.Mark()),
                     "unknown key '" + key + "' (expected drives)");
    }
  }
  if (!root["drives"]) ThrowFileError(path, 1, "no drives: (a list of drives)");
  const YAML::Node drives = root["drives"];
  if (!drives.IsSequence() || drives.size() == 0) {
    ThrowFileError(path, YamlLine(drives.Mark()), "drives: expected a list of at least one drive");
  }
  BatchManifest manifest;
  std::map<std::string, int> first_line;
  for (const YAML::Node& node : drives) {
    BatchDrive drive;
    DriveReader(path, node, &drive);
    const int line = YamlLine(node.Mark());
    const auto [earlier, inserted] = first_line.emplace(drive.name, line);
    if (!inserted) {
      ThrowFileError(path, line,
                     "drive name '" + drive.name + "' appears twice (first on line " +
                         std::to_string(earlier->second) + ")");
    }
    manifest.drives.push_back(drive);
  }
  return manifest;
}

std::vector<std::string> ParseSequenceList(const std::string& text) {
  const auto fail = [&text](const std::string& why) {
    throw Error("--sequences '" + text + "': " + why +
                " (expected names or ranges of digits such as 00-10 or 00,02,05-07)");
  };
  const auto is_number = [](const std::string& part) {
    return !part.empty() && part.size() <= 6 && std::all_of(part.begin(), part.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
  };
  std::vector<std::string> names;
  std::set<std::string> seen;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, comma - start);
    const size_t dash = part.find('-');
    const std::string first = part.substr(0, dash);
    const std::string last = dash == std::string::npos ? first : part.substr(dash + 1);
    if (!is_number(first) || !is_number(last)) fail("'" + part + "' is not a sequence or range");
    const int begin = std::stoi(first);
    const int end = std::stoi(last);
    if (end < begin) fail("the range '" + part + "' runs backwards");
    for (int number = begin; number <= end; ++number) {
      std::string name = std::to_string(number);
      if (name.size() < first.size()) name.insert(0, first.size() - name.size(), '0');
      if (!seen.insert(name).second) fail("sequence " + name + " is listed twice");
      names.push_back(name);
    }
    start = comma + 1;
  }
  return names;
}

BatchManifest KittiBatchManifest(const std::string& root, const std::string& sequences) {
  BatchManifest manifest;
  for (const std::string& name : ParseSequenceList(sequences)) {
    BatchDrive drive;
    drive.name = name;
    drive.kitti = (fs::absolute(root) / "sequences" / name).lexically_normal().string();
    if (!fs::is_directory(drive.kitti)) {
      ThrowFileError(drive.kitti, "no such KITTI sequence folder (--kitti-root " + root +
                                      " --sequences " + sequences + ")");
    }
    manifest.drives.push_back(drive);
  }
  return manifest;
}

}  // namespace roadscale::batch
