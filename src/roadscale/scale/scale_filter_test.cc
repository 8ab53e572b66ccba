#include "roadscale/scale/scale_filter.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

// Smoothed by hand: s'_i = sum_j w_ij s_j / sum_j w_ij with w_ij = exp(-(i-j)^2 / (2 sigma^2)).
// For sigma = 5 the window [1.0, 1.1, 0.9, 1.0, 2.0] becomes [1.16392, 1.17743, 1.19164,
// 1.20651, 1.22201]; for sigma = 3 [1.11307, 1.14234, 1.17700, 1.21665, 1.26049].
TEST(ScaleFilter, KnownWindow) {
  const std::vector<double> window = {1.0, 1.1, 0.9, 1.0, 2.0};
  EXPECT_NEAR(ScaleFilter::FilterWindow(window, 5.0), 1.1916386753649189, 1e-12);
  EXPECT_NEAR(ScaleFilter::FilterWindow(window, 3.0), 1.1770005913530155, 1e-12);
  // Without smoothing it is the plain median; with a very wide Gaussian, the mean.
  EXPECT_DOUBLE_EQ(ScaleFilter::FilterWindow(window, 0.0), 1.0);
  EXPECT_NEAR(ScaleFilter::FilterWindow(window, 1e6), 1.2, 1e-9);
  // An even count takes the mean of the two middle values.
  EXPECT_NEAR(ScaleFilter::FilterWindow({1.0, 1.2}, 5.0), 1.1, 1e-12);
  EXPECT_TRUE(std::isnan(ScaleFilter::FilterWindow({}, 5.0)));
}

TEST(ScaleFilter, KeepsTheLastQScales) {
  ScaleFilter filter;  // q = 5, sigma = 5
  EXPECT_TRUE(std::isnan(filter.Current()));
  EXPECT_DOUBLE_EQ(filter.Add(0.5), 0.5);
  for (double raw : {9.0, 1.0, 1.1, 0.9, 1.0}) filter.Add(raw);
  // 0.5 and 9.0 have left the window: [1.0, 1.1, 0.9, 1.0, 2.0] remains after one more.
  EXPECT_EQ(filter.size(), 5U);
  EXPECT_NEAR(filter.Add(2.0), 1.1916386753649189, 1e-12);
  EXPECT_NEAR(filter.Current(), 1.1916386753649189, 1e-12);
  // Values that are no scale are not added.
  EXPECT_NEAR(filter.Add(std::numeric_limits<double>::quiet_NaN()), 1.1916386753649189, 1e-12);
  EXPECT_NEAR(filter.Add(-1.0), 1.1916386753649189, 1e-12);
  EXPECT_EQ(filter.size(), 5U);
  filter.Reset();
  EXPECT_EQ(filter.size(), 0U);
  EXPECT_TRUE(std::isnan(filter.Current()));
}

TEST(ScaleFilter, ClampLimitsTheChangePerFrame) {
  ScaleFilterOptions options;
  options.window = 1;
  options.max_change_per_frame = 0.3;
  ScaleFilter filter(options);
  EXPECT_DOUBLE_EQ(filter.Add(1.0), 1.0);
  EXPECT_DOUBLE_EQ(filter.Add(2.0), 1.3);
  EXPECT_DOUBLE_EQ(filter.Add(2.0), 1.6);
  EXPECT_DOUBLE_EQ(filter.Add(1.5), 1.5);
  EXPECT_DOUBLE_EQ(filter.Add(0.1), 1.2);
}

TEST(ScaleFilterOptions, CheckRejectsBadValues) {
  ScaleFilterOptions options;
  EXPECT_EQ(options.window, 5);
  EXPECT_EQ(options.gaussian_sigma, 5.0);
  EXPECT_EQ(options.max_change_per_frame, 0.0);
  options.window = 0;
  EXPECT_THROW(options.Check(), Error);
  EXPECT_THROW(ScaleFilter{options}, Error);
  options = ScaleFilterOptions();
  options.gaussian_sigma = -1.0;
  EXPECT_THROW(options.Check(), Error);
}

}  // namespace
}  // namespace roadscale
