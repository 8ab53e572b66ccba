#include "roadscale/util/string_printf.h"

#include <gtest/gtest.h>

namespace roadscale {
namespace {

TEST(StringPrintf, FormatsLikePrintf) {
  EXPECT_EQ(StringPrintf("%d %s %.2f %%", 7, "m", 1.655), "7 m 1.66 %");
  EXPECT_EQ(StringPrintf("%s", ""), "");
}

TEST(StringPrintf, KeepsTextLongerThanAnyFixedBuffer) {
  const std::string long_word(5000, 'x');
  EXPECT_EQ(StringPrintf("<%s>", long_word.c_str()), "<" + long_word + ">");
}

}  // namespace
}  // namespace roadscale
