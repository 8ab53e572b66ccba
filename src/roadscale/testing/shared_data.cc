#include "roadscale/testing/shared_data.h"

namespace roadscale::testing {

std::filesystem::path SharedPath(const std::string& relative) { return SharedDataDir() / relative; }

std::string MissingSharedDataMessage(const std::string& relative) {
  const std::filesystem::path path = SharedPath(relative);
  if (std::filesystem::exists(path)) return "";
  return "shared data missing: " + path.string() +
         " (set ROADSCALE_SHARED to the folder with kitti/ and models/)";
}

}  // namespace roadscale::testing
