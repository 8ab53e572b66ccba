#pragma once

#include <string>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale::testing {

// The message of the roadscale::Error that `call` throws; a test failure when it throws none.
template <typename Function>
std::string ErrorOf(Function call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an Error";
  return "";
}

}  // namespace roadscale::testing
