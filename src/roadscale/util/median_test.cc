#include "roadscale/util/median.h"

#include <gtest/gtest.h>

namespace roadscale {
namespace {

TEST(Median, OddEvenAndNone) {
  EXPECT_DOUBLE_EQ(Median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(Median({4.0, 1.0, 3.0, 2.0}), 3.0);  // the upper middle value
  EXPECT_DOUBLE_EQ(Median({-5.0}), -5.0);
  EXPECT_DOUBLE_EQ(Median({}), 0.0);
}

}  // namespace
}  // namespace roadscale
