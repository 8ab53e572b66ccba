#include "roadscale/io/image_codecs.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <dlfcn.h>
#include <link.h>

#include "roadscale/io/codecs_plugin.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

const RoadscaleCodecs* OpenPluginAt(const std::string& path) {
  void* plugin = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (plugin == nullptr) {
    throw Error("cannot load roadscale's image codecs plugin " + path + ": " + dlerror());
  }
  const auto entry = reinterpret_cast<CodecsEntryPoint>(dlsym(plugin, kCodecsEntryPoint));
  if (entry == nullptr) {
    throw Error(path + ": not roadscale's image codecs plugin (no " +
                std::string(kCodecsEntryPoint) + ")");
  }
  return entry();
}

bool Exists(const std::string& path) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}

// The file of the program or shared library (a Python module) this code is linked into.
std::string ObjectOfThisCode() {
  struct Search {
    uintptr_t address = 0;
    std::string object;
  } search{reinterpret_cast<uintptr_t>(&ObjectOfThisCode), ""};
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        auto* search = static_cast<Search*>(data);
        for (int i = 0; i < info->dlpi_phnum; ++i) {
          const ElfW(Phdr)& segment = info->dlpi_phdr[i];
          const uintptr_t start = info->dlpi_addr + segment.p_vaddr;
          if (segment.p_type == PT_LOAD && search->address >= start &&
              search->address < start + segment.p_memsz) {
            // The program itself has no name here; the kernel knows its file.
            search->object = info->dlpi_name[0] != '\0' ? info->dlpi_name : "/proc/self/exe";
            return 1;
          }
        }
        return 0;
      },
      &search);
  return search.object;
}

bool LinkedIntoTheBuildTree() {
  std::error_code error;
  const std::filesystem::path object = std::filesystem::canonical(ObjectOfThisCode(), error);
  if (error) return false;
  const std::filesystem::path tree = std::filesystem::canonical(ROADSCALE_BUILD_DIR, error);
  if (error) return false;
  const auto [end, unused] = std::mismatch(tree.begin(), tree.end(), object.begin(), object.end());
  return end == tree.end();
}

const RoadscaleCodecs* OpenPlugin() {
  // A plugin named by the user is the only one tried: another found instead would hide the
  // mistake.
  const char* chosen = std::getenv("ROADSCALE_CODECS_PLUGIN");
  if (chosen != nullptr && *chosen != '\0') {
    if (!Exists(chosen)) {
      throw Error(std::string("ROADSCALE_CODECS_PLUGIN=") + chosen +
                  ": no such file (roadscale's image codecs plugin)");
    }
    return OpenPluginAt(chosen);
  }
  // Only a program of the build tree takes the build's plugin: an installed program (or one
  // built against the installed libraries) that took it would load whatever the tree holds
  // today, perhaps of another version than its own.
  const char* path =
      LinkedIntoTheBuildTree() ? ROADSCALE_CODECS_BUILD_PATH : ROADSCALE_CODECS_INSTALL_PATH;
  if (Exists(path)) return OpenPluginAt(path);
  throw Error(std::string("roadscale's image codecs plugin is missing (looked for ") + path +
              "; set ROADSCALE_CODECS_PLUGIN to its path)");
}

// Opened once, on first use, and kept: OpenCV's codecs stay loaded to the process's end.
const RoadscaleCodecs& Codecs() {
  static const RoadscaleCodecs* const codecs = OpenPlugin();
  return *codecs;
}

}  // namespace

cv::Mat DecodeImage(const std::string& bytes, int flags) {
  cv::Mat image;
  Codecs().decode(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), flags,
                  &image);
  return image;
}

bool WriteImage(const std::string& path, const cv::Mat& image) {
  return Codecs().write(path.c_str(), &image);
}

VideoReader::~VideoReader() {
  if (video_ != nullptr) Codecs().video_close(video_);
}

bool VideoReader::Open(const std::string& path) {
  if (video_ != nullptr) Codecs().video_close(video_);
  video_ = Codecs().video_open(path.c_str());
  return video_ != nullptr;
}

double VideoReader::Get(int property) const {
  return video_ != nullptr ? Codecs().video_get(video_, property) : 0.0;
}

bool VideoReader::Grab() { return video_ != nullptr && Codecs().video_grab(video_); }

bool VideoReader::Retrieve(cv::Mat* image) {
  return video_ != nullptr && Codecs().video_retrieve(video_, image);
}

}  // namespace roadscale
