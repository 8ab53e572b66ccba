#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "roadscale/util/shared_data.h"

namespace roadscale::testing {

// Path of a file or folder under the shared data folder (see SharedDataDir()).
std::filesystem::path SharedPath(const std::string& relative);

// Empty when the shared path exists, else a message naming what is missing.
std::string MissingSharedDataMessage(const std::string& relative);

}  // namespace roadscale::testing

// Skips the current test, saying what is missing, when a shared file is absent, so that a
// build without ../shared still passes its unit tests and says why data tests were skipped.
#define ROADSCALE_REQUIRE_SHARED(relative)                             \
  do {                                                                 \
    const std::string roadscale_missing =                              \
        ::roadscale::testing::MissingSharedDataMessage(relative);      \
    if (!roadscale_missing.empty()) GTEST_SKIP() << roadscale_missing; \
  } while (false)
