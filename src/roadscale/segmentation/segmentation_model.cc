#include "roadscale/segmentation/segmentation_model.h"

#include <cmath>
#include <set>
#include <utility>

#include <yaml-cpp/yaml.h>

#include "roadscale/util/error.h"
#include "roadscale/util/shared_data.h"
#include "roadscale/util/yaml_file.h"

namespace roadscale {
namespace {

namespace fs = std::filesystem;

// Reads YAML values with errors that name the file, the line and the key.
class ModelFileReader {
 public:
  ModelFileReader(std::string path, YAML::Node root) : path_(std::move(path)), root_(root) {}

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& message) const {
    const int line = node.IsDefined() && node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
    ThrowFileError(path_, line, message);
  }

  void CheckKeys(const std::set<std::string>& allowed, const std::string& backend) const {
    for (const auto& entry : root_) {
      const std::string key = entry.first.as<std::string>();
      if (allowed.count(key) == 0) {
        std::string names;
        for (const std::string& name : allowed) names += (names.empty() ? "" : ", ") + name;
        Fail(entry.first, "unknown key '" + key + "' for backend " + backend +
                              " (expected one of: " + names + ")");
      }
    }
  }

  bool Has(const std::string& key) const { return static_cast<bool>(root_[key]); }

  YAML::Node Required(const std::string& key, const std::string& expected) const {
    const YAML::Node node = root_[key];
    if (!node) ThrowFileError(path_, "missing key '" + key + "' (expected " + expected + ")");
    return node;
  }

  std::string String(const std::string& key, const std::string& expected) const {
    const YAML::Node node = Required(key, expected);
    if (!node.IsScalar()) Fail(node, "'" + key + "' must be " + expected);
    return node.Scalar();
  }

  std::string Choice(const std::string& key, const std::set<std::string>& choices,
                     const std::string& fallback) const {
    std::string expected;
    for (const std::string& choice : choices) expected += (expected.empty() ? "" : " or ") + choice;
    if (!Has(key) && !fallback.empty()) return fallback;
    const std::string value = String(key, expected);
    if (choices.count(value) == 0) {
      Fail(root_[key], "'" + key + "' is '" + value + "', expected " + expected);
    }
    return value;
  }

  double Number(const YAML::Node& node, const std::string& key) const {
    double value = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
      Fail(node, "'" + key + "' must be a number, got '" + YAML::Dump(node) + "'");
    }
    return value;
  }

  int Integer(const YAML::Node& node, const std::string& key, int min_value) const {
    int value = 0;
    if (!node.IsScalar() || !YAML::convert<int>::decode(node, value)) {
      Fail(node, "'" + key + "' must be an integer, got '" + YAML::Dump(node) + "'");
    }
    if (value < min_value) {
      Fail(node, "'" + key + "' must be >= " + std::to_string(min_value) + ", got " +
                     std::to_string(value));
    }
    return value;
  }

  std::vector<int> IntegerList(const std::string& key, int min_value, int max_value) const {
    const YAML::Node node = root_[key];
    if (!node.IsSequence()) Fail(node, "'" + key + "' must be a list of integers, like [0, 1]");
    std::vector<int> values;
    for (const YAML::Node& item : node) {
      const int value = Integer(item, key, min_value);
      if (value > max_value) {
        Fail(item, "'" + key + "' values must be <= " + std::to_string(max_value) + ", got " +
                       std::to_string(value));
      }
      values.push_back(value);
    }
    return values;
  }

  std::array<double, 3> Triple(const std::string& key, const std::array<double, 3>& fallback,
                               bool positive) const {
    if (!Has(key)) return fallback;
    const YAML::Node node = root_[key];
    if (!node.IsSequence() || node.size() != 3) {
      Fail(node, "'" + key + "' must be a list of 3 numbers, one per channel");
    }
    std::array<double, 3> values{};
    for (size_t i = 0; i < 3; ++i) {
      values[i] = Number(node[i], key);
      if (positive && !(values[i] > 0.0)) Fail(node[i], "'" + key + "' values must be > 0");
    }
    return values;
  }

  const std::string& path() const { return path_; }
  const YAML::Node& root() const { return root_; }

 private:
  std::string path_;
  YAML::Node root_;
};

void ReadClassIds(const ModelFileReader& reader, MaskClasses* classes) {
  if (reader.Has("road_ids")) classes->road_ids = reader.IntegerList("road_ids", 0, 254);
  if (reader.Has("dynamic_ids")) classes->dynamic_ids = reader.IntegerList("dynamic_ids", 0, 254);
  if (classes->road_ids.empty()) {
    reader.Fail(reader.root()["road_ids"], "'road_ids' needs at least one class id");
  }
}

// A network outputs the train ids of its classes (train_ids, or the class indices
// 0..num_classes-1). A road id it never outputs leaves every frame without road, and so the
// whole run unscaled; a dynamic id it never outputs silently masks nothing. So every id the
// file lists must be one it outputs, and the default road id too.
void CheckIdsAreOutput(const ModelFileReader& reader, const OnnxModelSpec& spec,
                       const MaskClasses& classes) {
  std::set<int> output;
  for (int index = 0; index < spec.num_classes; ++index) {
    output.insert(spec.train_ids.empty() ? index : spec.train_ids[static_cast<size_t>(index)]);
  }
  const std::string outputs =
      spec.train_ids.empty()
          ? "its class indices 0.." + std::to_string(spec.num_classes - 1) + " are its train ids"
          : "see its train_ids";
  for (const auto& [key, ids] :
       {std::pair<std::string, const std::vector<int>*>{"road_ids", &classes.road_ids},
        {"dynamic_ids", &classes.dynamic_ids}}) {
    if (!reader.Has(key) && key == "dynamic_ids") continue;
    for (int id : *ids) {
      if (output.count(id) == 0) {
        reader.Fail(reader.root()[key], std::string(reader.Has(key) ? "" : "the default ") + "'" +
                                            key + "' holds " + std::to_string(id) +
                                            ", a train id the network never outputs (" + outputs +
                                            ")");
      }
    }
  }
}

OnnxModelSpec ReadOnnxSpec(const ModelFileReader& reader) {
  OnnxModelSpec spec;
  spec.file = ResolveModelFile(reader.path(), reader.String("file", "the path of an .onnx file"));

  const YAML::Node size = reader.Required("input_size", "[width, height]");
  if (!size.IsSequence() || size.size() != 2) {
    reader.Fail(size, "'input_size' must be [width, height], like [640, 192]");
  }
  spec.input_width = reader.Integer(size[0], "input_size", 1);
  spec.input_height = reader.Integer(size[1], "input_size", 1);
  // Beyond this a typo (100000) would try to allocate tens of GB for the input blob.
  constexpr int kMaxInputSide = 4096;
  if (spec.input_width > kMaxInputSide || spec.input_height > kMaxInputSide) {
    reader.Fail(size, "'input_size' sides must be <= " + std::to_string(kMaxInputSide) + ", got [" +
                          std::to_string(spec.input_width) + ", " +
                          std::to_string(spec.input_height) + "]");
  }

  spec.channel_order = reader.Choice("channel_order", {"rgb", "bgr"}, "") == "rgb"
                           ? ChannelOrder::kRgb
                           : ChannelOrder::kBgr;
  if (reader.Has("input_channels")) {
    const YAML::Node node = reader.root()["input_channels"];
    spec.input_channels = reader.Integer(node, "input_channels", 1);
    if (spec.input_channels != 1 && spec.input_channels != 3) {
      reader.Fail(node, "'input_channels' must be 1 or 3");
    }
  }
  if (reader.Has("scale")) spec.scale = reader.Number(reader.root()["scale"], "scale");
  spec.mean = reader.Triple("mean", spec.mean, false);
  spec.std = reader.Triple("std", spec.std, true);
  spec.output = reader.Choice("output", {"scores", "labels"}, "scores") == "scores"
                    ? OutputLayout::kScores
                    : OutputLayout::kLabels;
  spec.num_classes =
      reader.Integer(reader.Required("num_classes", "the number of classes the network outputs"),
                     "num_classes", 1);
  if (spec.num_classes > 255) {
    reader.Fail(reader.root()["num_classes"], "'num_classes' must be <= 255");
  }

  if (reader.Has("classes")) {
    const YAML::Node node = reader.root()["classes"];
    if (!node.IsSequence()) reader.Fail(node, "'classes' must be a list of class names");
    for (const YAML::Node& item : node) spec.class_names.push_back(item.as<std::string>(""));
    if (static_cast<int>(spec.class_names.size()) != spec.num_classes) {
      reader.Fail(node, "'classes' has " + std::to_string(spec.class_names.size()) +
                            " names but num_classes is " + std::to_string(spec.num_classes));
    }
  }
  if (reader.Has("train_ids")) {
    spec.train_ids = reader.IntegerList("train_ids", 0, 255);
    if (static_cast<int>(spec.train_ids.size()) != spec.num_classes) {
      reader.Fail(reader.root()["train_ids"],
                  "'train_ids' has " + std::to_string(spec.train_ids.size()) +
                      " entries but num_classes is " + std::to_string(spec.num_classes));
    }
  }
  return spec;
}

LabelImageSpec ReadLabelImageSpec(const ModelFileReader& reader) {
  LabelImageSpec spec;
  const fs::path folder = reader.String("folder", "the folder of the label PNGs");
  spec.folder = folder.is_absolute() ? folder : fs::path(reader.path()).parent_path() / folder;
  std::error_code error;
  if (!fs::is_directory(spec.folder, error)) {
    reader.Fail(reader.root()["folder"], "label folder " + spec.folder.string() + " not found");
  }
  spec.ids = reader.Choice("ids", {"train_ids", "label_ids"}, "") == "train_ids"
                 ? LabelIdSpace::kTrainIds
                 : LabelIdSpace::kCityscapesLabelIds;
  if (reader.Has("resize")) {
    const YAML::Node node = reader.root()["resize"];
    bool resize = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, resize)) {
      reader.Fail(node, "'resize' must be true or false");
    }
    spec.resize = resize;
  }
  return spec;
}

}  // namespace

fs::path ResolveModelFile(const std::string& yaml_path, const std::string& file) {
  // The error_code forms: a name the file system refuses (too long, a symlink loop) is "not
  // found" here, not an exception of another type.
  const auto is_file = [](const fs::path& path) {
    std::error_code ignored;
    return fs::is_regular_file(path, ignored);
  };
  const fs::path relative(file);
  if (relative.is_absolute()) {
    if (!is_file(relative)) ThrowFileError(yaml_path, "model file " + file + " not found");
    return relative;
  }
  const fs::path beside = fs::path(yaml_path).parent_path() / relative;
  if (is_file(beside)) return beside;
  const fs::path shared = SharedDataDir() / relative;
  if (is_file(shared)) return shared;
  ThrowFileError(yaml_path, "model file " + file + " not found, neither at " + beside.string() +
                                " nor at " + shared.string() +
                                " (set ROADSCALE_SHARED to the shared data folder)");
}

SegmentationModel ReadSegmentationModel(const std::string& yaml_path) {
  const YAML::Node root = LoadYamlFile(yaml_path, "segmentation model file");
  if (!root.IsMap()) {
    ThrowFileError(yaml_path,
                   "expected a YAML mapping with a 'backend' key (onnx, label_images "
                   "or none)");
  }
  const ModelFileReader reader(yaml_path, root);
  SegmentationModel model;
  model.yaml_path = yaml_path;
  const std::string backend = reader.Choice("backend", {"onnx", "label_images", "none"}, "");
  if (backend == "none") {
    reader.CheckKeys({"backend"}, backend);
    model.backend = SegmentationBackend::kNone;
    return model;
  }
  if (backend == "onnx") {
    reader.CheckKeys(
        {"backend", "file", "input_size", "channel_order", "input_channels", "scale", "mean", "std",
         "output", "num_classes", "classes", "train_ids", "road_ids", "dynamic_ids"},
        backend);
    model.backend = SegmentationBackend::kOnnx;
    model.onnx = ReadOnnxSpec(reader);
  } else {
    reader.CheckKeys({"backend", "folder", "ids", "resize", "road_ids", "dynamic_ids"}, backend);
    model.backend = SegmentationBackend::kLabelImages;
    model.label_images = ReadLabelImageSpec(reader);
  }
  ReadClassIds(reader, &model.classes);
  if (model.backend == SegmentationBackend::kOnnx) {
    CheckIdsAreOutput(reader, model.onnx, model.classes);
  }
  return model;
}

}  // namespace roadscale
