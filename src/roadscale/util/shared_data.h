#pragma once

#include <filesystem>

namespace roadscale {

// The folder with the shared KITTI data and models: $ROADSCALE_SHARED when set, else the
// location configured at build time (../shared beside the source tree).
std::filesystem::path SharedDataDir();

}  // namespace roadscale
