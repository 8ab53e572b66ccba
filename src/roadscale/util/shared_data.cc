#include "roadscale/util/shared_data.h"

#include <cstdlib>

namespace roadscale {

std::filesystem::path SharedDataDir() {
  const char* from_environment = std::getenv("ROADSCALE_SHARED");
  if (from_environment != nullptr && from_environment[0] != '\0') return from_environment;
  return ROADSCALE_DEFAULT_SHARED_DIR;
}

}  // namespace roadscale
