#include "roadscale/io/camera_setup.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "roadscale/geometry/camera_height.h"
#include "roadscale/geometry/field_of_view.h"
#include "roadscale/io/distortion_check.h"
#include "roadscale/util/atomic_file.h"
#include "roadscale/util/error.h"
#include "roadscale/util/yaml_file.h"

namespace roadscale {
namespace {

YAML::Node RequireKey(const YAML::Node& block, const char* key, const std::string& path) {
  const YAML::Node node = block[key];
  if (!node) {
    ThrowFileError(path, YamlLine(block.Mark()),
                   std::string("Camera: missing key '") + key + "' (expected " +
                       "fx, fy, cx, cy, width, height, h0)");
  }
  if (!node.IsScalar()) {
    ThrowFileError(path, YamlLine(node.Mark()),
                   std::string("Camera.") + key + ": expected a number");
  }
  return node;
}

double ReadDouble(const YAML::Node& block, const char* key, const std::string& path) {
  const YAML::Node node = RequireKey(block, key, path);
  const std::string& text = node.Scalar();
  char* end = nullptr;
  // strtod's ERANGE is not checked: an overflow is infinite (refused below), and an underflow
  // (k1: 1e-320) is a number, as close to 0 as a double gets; the range checks judge it.
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    ThrowFileError(path, YamlLine(node.Mark()),
                   std::string("Camera.") + key + ": expected a number, found '" + text + "'");
  }
  return value;
}

int ReadInt(const YAML::Node& block, const char* key, const std::string& path) {
  const YAML::Node node = RequireKey(block, key, path);
  const std::string& text = node.Scalar();
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    ThrowFileError(path, YamlLine(node.Mark()),
                   std::string("Camera.") + key + ": expected an integer, found '" + text + "'");
  }
  return value;
}

// OpenCV's order; only the rational model's k4..k6 make the vector 8 long.
constexpr const char* kDistortionKeys[] = {"k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6"};

// The optional distortion keys: none given is an undistorted camera, missing ones are 0.
std::vector<double> ReadDistortion(const YAML::Node& block, const std::string& path) {
  std::vector<double> coefficients(8, 0.0);
  size_t used = 0;
  for (size_t i = 0; i < coefficients.size(); ++i) {
    if (!block[kDistortionKeys[i]]) continue;
    coefficients[i] = ReadDouble(block, kDistortionKeys[i], path);
    used = i < 5 ? std::max<size_t>(used, 5) : 8;
  }
  coefficients.resize(used);
  return coefficients;
}

// Every key a Camera: block may hold; `name` is a label for people, not read.
constexpr const char* kCameraKeys[] = {"name", "fx", "fy", "cx", "cy", "width", "height", "h0",
                                       "k1",   "k2", "p1", "p2", "k3", "k4",    "k5",     "k6"};

// A typo (K1:) or a term of a model roadscale does not implement (OpenCV's thin prism s1, k7)
// would silently drop that term: every other key is an error.
void RejectUnknownKeys(const YAML::Node& block, const std::string& path) {
  for (const auto& item : block) {
    const std::string key = item.first.as<std::string>();
    if (std::find(std::begin(kCameraKeys), std::end(kCameraKeys), key) == std::end(kCameraKeys)) {
      ThrowFileError(path, YamlLine(item.first.Mark()),
                     "unknown key 'Camera." + key +
                         "' (expected fx, fy, cx, cy, width, height, h0, name and OpenCV's "
                         "distortion k1, k2, p1, p2, k3, k4, k5, k6)");
    }
  }
}

// The shortest text that reads back as the same double.
std::string ShortestRoundTrip(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace

void CameraSetup::Check() const {
  camera.Check();
  CheckOption(camera.cx >= 0.0 && camera.cx <= camera.width && camera.cy >= 0.0 &&
                  camera.cy <= camera.height,
              "camera.cx/cy", "the principal point must lie inside the image");
  CheckFocalLength(camera.fx, camera.width, "camera.fx");
  CheckFocalLength(camera.fy, camera.height, "camera.fy");
  CheckCameraHeight(h0, "camera.h0");
  CheckOption(distortion.empty() || distortion.size() == 5 || distortion.size() == 8,
              "camera.distortion", "needs 0, 5 (k1 k2 p1 p2 k3) or 8 (with k4 k5 k6) coefficients");
  for (double coefficient : distortion) {
    CheckOption(std::isfinite(coefficient), "camera.distortion", "coefficients must be finite");
  }
  CheckDistortionMap(camera, distortion);
}

CameraSetup ReadCameraYaml(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path, "camera YAML file");
  if (!root.IsMap()) ThrowFileError(path, "expected a YAML map with a top-level 'Camera:' block");
  const YAML::Node block = root["Camera"];
  if (!block) ThrowFileError(path, "missing the top-level 'Camera:' block");
  if (!block.IsMap()) {
    ThrowFileError(path, YamlLine(block.Mark()),
                   "'Camera:' must be a block of keys (fx, fy, cx, cy, width, height, h0)");
  }
  RejectUnknownKeys(block, path);

  CameraSetup setup;
  setup.camera.fx = ReadDouble(block, "fx", path);
  setup.camera.fy = ReadDouble(block, "fy", path);
  setup.camera.cx = ReadDouble(block, "cx", path);
  setup.camera.cy = ReadDouble(block, "cy", path);
  setup.camera.width = ReadInt(block, "width", path);
  setup.camera.height = ReadInt(block, "height", path);
  setup.h0 = ReadDouble(block, "h0", path);
  setup.distortion = ReadDistortion(block, path);
  try {
    setup.Check();
  } catch (const Error& e) {
    ThrowFileError(path, YamlLine(block.Mark()), std::string("Camera: ") + e.what());
  }
  return setup;
}

void WriteCameraYaml(const std::string& path, const CameraSetup& setup) {
  try {
    setup.Check();
  } catch (const Error& e) {
    ThrowFileError(path, std::string("refusing to write an invalid camera: ") + e.what());
  }
  std::ostringstream file;
  const PinholeCamera& c = setup.camera;
  file << "# Pinhole camera (of the undistorted image), pixels; h0: camera height above the "
          "road, m;\n# k1.. p2..: lens distortion (OpenCV's model), when there is any.\n"
       << "Camera:\n"
       << "  fx: " << ShortestRoundTrip(c.fx) << '\n'
       << "  fy: " << ShortestRoundTrip(c.fy) << '\n'
       << "  cx: " << ShortestRoundTrip(c.cx) << '\n'
       << "  cy: " << ShortestRoundTrip(c.cy) << '\n'
       << "  width: " << c.width << '\n'
       << "  height: " << c.height << '\n'
       << "  h0: " << ShortestRoundTrip(setup.h0) << '\n';
  for (size_t i = 0; i < setup.distortion.size(); ++i) {
    file << "  " << kDistortionKeys[i] << ": " << ShortestRoundTrip(setup.distortion[i]) << '\n';
  }
  WriteFileAtomically(path, file.str());
}

}  // namespace roadscale
