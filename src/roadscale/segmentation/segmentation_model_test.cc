#include "roadscale/segmentation/segmentation_model.h"

#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "roadscale/testing/shared_data.h"
#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

using testing::TempDir;
using testing::WriteTextFile;

// The message of the Error that reading `yaml` throws; fails the test when none is thrown.
std::string ReadError(const std::string& yaml_path) {
  try {
    ReadSegmentationModel(yaml_path);
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << yaml_path;
  return "";
}

class SegmentationModelTest : public ::testing::Test {
 protected:
  SegmentationModelTest() { WriteTextFile(dir_.File("net.onnx"), "placeholder"); }

  std::string Yaml(const std::string& text) { return WriteTextFile(dir_.File("model.yaml"), text); }

  static std::string OnnxYaml(const std::string& extra = "") {
    return "backend: onnx\nfile: net.onnx\ninput_size: [64, 32]\nchannel_order: bgr\n"
           "num_classes: 3\n" +
           extra;
  }

  TempDir dir_;
};

TEST_F(SegmentationModelTest, ReadsAnOnnxDescriptionWithDefaults) {
  const SegmentationModel model = ReadSegmentationModel(Yaml(OnnxYaml()));
  EXPECT_EQ(model.backend, SegmentationBackend::kOnnx);
  EXPECT_EQ(model.onnx.file, dir_.path() / "net.onnx");
  EXPECT_EQ(model.onnx.input_width, 64);
  EXPECT_EQ(model.onnx.input_height, 32);
  EXPECT_EQ(model.onnx.channel_order, ChannelOrder::kBgr);
  EXPECT_EQ(model.onnx.input_channels, 3);
  EXPECT_EQ(model.onnx.scale, 1.0);
  EXPECT_EQ(model.onnx.output, OutputLayout::kScores);
  EXPECT_EQ(model.onnx.num_classes, 3);
  EXPECT_TRUE(model.onnx.train_ids.empty());
  EXPECT_EQ(model.classes.road_ids, std::vector<int>{0});
  EXPECT_EQ(model.classes.dynamic_ids, (std::vector<int>{11, 12, 13, 14, 15, 16, 17, 18}));
}

TEST_F(SegmentationModelTest, ReadsEveryOnnxKey) {
  const SegmentationModel model = ReadSegmentationModel(Yaml(OnnxYaml(
      "input_channels: 1\nscale: 0.00392156862745098\nmean: [0.485, 0.456, 0.406]\n"
      "std: [0.229, 0.224, 0.225]\noutput: labels\nclasses: [a, b, c]\ntrain_ids: [0, 13, 1]\n"
      "road_ids: [0, 1]\ndynamic_ids: [13]\n")));
  EXPECT_EQ(model.onnx.input_channels, 1);
  EXPECT_DOUBLE_EQ(model.onnx.scale, 1.0 / 255.0);
  EXPECT_DOUBLE_EQ(model.onnx.mean[2], 0.406);
  EXPECT_DOUBLE_EQ(model.onnx.std[0], 0.229);
  EXPECT_EQ(model.onnx.output, OutputLayout::kLabels);
  EXPECT_EQ(model.onnx.class_names, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(model.onnx.train_ids, (std::vector<int>{0, 13, 1}));
  EXPECT_EQ(model.classes.road_ids, (std::vector<int>{0, 1}));
  EXPECT_EQ(model.classes.dynamic_ids, std::vector<int>{13});
}

TEST_F(SegmentationModelTest, UnknownKeyNamesTheKeyAndTheLine) {
  const std::string message = ReadError(Yaml(OnnxYaml("chanel_order: rgb\n")));
  EXPECT_NE(message.find("model.yaml:6: unknown key 'chanel_order'"), std::string::npos) << message;
  EXPECT_NE(message.find("channel_order"), std::string::npos) << message;
}

TEST_F(SegmentationModelTest, MissingOrWrongValuesSayWhatWasExpected) {
  struct Case {
    std::string yaml;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"file: net.onnx\n", "missing key 'backend'"},
      {"backend: tensorrt\n", "'backend' is 'tensorrt', expected label_images or none or onnx"},
      {"backend: onnx\nfile: net.onnx\ninput_size: [64, 32]\nnum_classes: 3\n",
       "missing key 'channel_order'"},
      {"backend: onnx\nfile: net.onnx\nchannel_order: rgb\nnum_classes: 3\n",
       "missing key 'input_size'"},
      {"backend: onnx\nfile: net.onnx\ninput_size: [64]\nchannel_order: rgb\nnum_classes: 3\n",
       "model.yaml:3: 'input_size' must be [width, height]"},
      {"backend: onnx\nfile: net.onnx\ninput_size: [64, 0]\nchannel_order: rgb\nnum_classes: 3\n",
       "'input_size' must be >= 1"},
      {OnnxYaml("scale: fast\n"), "model.yaml:6: 'scale' must be a number"},
      {OnnxYaml("std: [1, 0, 1]\n"), "'std' values must be > 0"},
      {OnnxYaml("mean: [1, 2]\n"), "'mean' must be a list of 3 numbers"},
      {OnnxYaml("classes: [a, b]\n"), "'classes' has 2 names but num_classes is 3"},
      {OnnxYaml("train_ids: [0, 1, 256]\n"), "'train_ids' values must be <= 255"},
      {OnnxYaml("output: logits\n"), "'output' is 'logits', expected labels or scores"},
      {OnnxYaml("road_ids: []\n"), "'road_ids' needs at least one class id"},
      {OnnxYaml("input_channels: 2\n"), "'input_channels' must be 1 or 3"},
      {"backend: none\nfile: x.onnx\n", "unknown key 'file' for backend none"},
      {"backend: label_images\nfolder: .\n", "missing key 'ids'"},
      {"- backend: onnx\n", "expected a YAML mapping"},
      {"backend: onnx\nfile: [a, b\n", "invalid YAML"},
      {"backend: onnx\nfile: net.onnx\ninput_size: [100000, 100000]\nchannel_order: rgb\n"
       "num_classes: 3\n",
       "model.yaml:3: 'input_size' sides must be <= 4096, got [100000, 100000]"},
      {OnnxYaml("road_ids: [0, 7]\n"),
       "model.yaml:6: 'road_ids' holds 7, a train id the network never outputs (its class indices "
       "0..2 are its train ids)"},
      {OnnxYaml("dynamic_ids: [13]\n"), "'dynamic_ids' holds 13, a train id the network never"},
      {OnnxYaml("train_ids: [3, 255, 13]\n"),
       "the default 'road_ids' holds 0, a train id the network never outputs (see its "
       "train_ids)"},
      {OnnxYaml("num_classes: 3\n"), "key 'num_classes' appears twice in one mapping"},
      // A name longer than the file system allows: "not found", not a filesystem_error.
      {"backend: onnx\nfile: " + std::string(5000, 'x') +
           "\ninput_size: [64, 32]\n"
           "channel_order: rgb\nnum_classes: 3\n",
       "model.yaml: model file xxxx"},
  };
  for (const Case& c : cases) {
    const std::string message = ReadError(Yaml(c.yaml));
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "yaml:\n"
        << c.yaml << "message: " << message << "\nexpected: " << c.expected;
    EXPECT_EQ(message.find(dir_.File("model.yaml")), 0u) << message;
  }
}

TEST_F(SegmentationModelTest, MissingModelFileNamesBothPlacesLookedAt) {
  const std::string message = ReadError(
      Yaml("backend: onnx\nfile: models/none.onnx\ninput_size: [8, 8]\nchannel_order: rgb\n"
           "num_classes: 3\n"));
  EXPECT_NE(message.find((dir_.path() / "models/none.onnx").string()), std::string::npos)
      << message;
  EXPECT_NE(message.find((SharedDataDir() / "models/none.onnx").string()), std::string::npos)
      << message;
  EXPECT_NE(
      ReadError(dir_.File("absent.yaml")).find("cannot open segmentation model file: no such file"),
      std::string::npos);
  EXPECT_NE(
      ReadError(dir_.path().string()).find("cannot open segmentation model file: is a directory"),
      std::string::npos);
}

TEST_F(SegmentationModelTest, RelativeModelFilesAreLookedUpBesideTheYamlThenInTheSharedFolder) {
  TempDir shared;
  WriteTextFile(shared.File("models/in_shared.onnx"), "x");
  const char* previous = std::getenv("ROADSCALE_SHARED");
  const std::string saved = previous != nullptr ? previous : "";
  setenv("ROADSCALE_SHARED", shared.path().c_str(), 1);
  const std::string yaml = Yaml("");
  EXPECT_EQ(ResolveModelFile(yaml, "models/in_shared.onnx"),
            shared.path() / "models/in_shared.onnx");
  WriteTextFile(dir_.File("models/in_shared.onnx"), "beside");
  EXPECT_EQ(ResolveModelFile(yaml, "models/in_shared.onnx"), dir_.path() / "models/in_shared.onnx");
  EXPECT_EQ(ResolveModelFile(yaml, shared.File("models/in_shared.onnx")),
            shared.path() / "models/in_shared.onnx");
  if (previous != nullptr) {
    setenv("ROADSCALE_SHARED", saved.c_str(), 1);
  } else {
    unsetenv("ROADSCALE_SHARED");
  }
}

TEST_F(SegmentationModelTest, NoneAndLabelImageBackends) {
  EXPECT_EQ(ReadSegmentationModel(Yaml("backend: none\n")).backend, SegmentationBackend::kNone);
  std::filesystem::create_directories(dir_.path() / "labels");
  const SegmentationModel labels = ReadSegmentationModel(
      Yaml("backend: label_images\nfolder: labels\nids: label_ids\nresize: true\n"));
  EXPECT_EQ(labels.backend, SegmentationBackend::kLabelImages);
  EXPECT_EQ(labels.label_images.folder, dir_.path() / "labels");
  EXPECT_EQ(labels.label_images.ids, LabelIdSpace::kCityscapesLabelIds);
  EXPECT_TRUE(labels.label_images.resize);
}

TEST(ShippedModels, EveryEspnetv2DescriptionFindsItsNetwork) {
  ROADSCALE_REQUIRE_SHARED("models/espnetv2");
  for (const char* size : {"640x192", "512x256", "1024x320", "1024x512"}) {
    const std::string yaml =
        std::string(ROADSCALE_SOURCE_DIR) + "/config/models/espnetv2_" + size + ".yaml";
    const SegmentationModel model = ReadSegmentationModel(yaml);
    EXPECT_EQ(model.onnx.file.filename().string(),
              std::string("espnetv2_s2.0_city_") + size + ".onnx");
    EXPECT_EQ(
        std::to_string(model.onnx.input_width) + "x" + std::to_string(model.onnx.input_height),
        size);
    EXPECT_EQ(model.onnx.class_names.size(), 20u);
    EXPECT_EQ(model.onnx.class_names[13], "car");
  }
}

}  // namespace
}  // namespace roadscale
