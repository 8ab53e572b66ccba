#include "roadscale/synth/procedural_texture.h"

#include <cmath>

#include <gtest/gtest.h>

namespace roadscale::synth {
namespace {

TEST(ProceduralTexture, FilteredPulseIsTheBoxFilteredPulseTrain) {
  // Point samples.
  EXPECT_EQ(FilteredPulse(0.05, 1.0, 0.1, 0.0, 0.0), 1.0);
  EXPECT_EQ(FilteredPulse(0.15, 1.0, 0.1, 0.0, 0.0), 0.0);
  EXPECT_EQ(FilteredPulse(-0.95, 1.0, 0.1, 0.0, 0.0), 1.0);
  // A footprint of whole periods sees the duty cycle.
  EXPECT_NEAR(FilteredPulse(0.37, 1.0, 0.1, 0.0, 3.0), 0.1, 1e-12);
  // Half the footprint on the pulse.
  EXPECT_NEAR(FilteredPulse(0.1, 1.0, 0.1, 0.0, 0.1), 0.5, 1e-12);
  EXPECT_NEAR(FilteredBox(0.1, 0.0, 0.1, 0.1), 0.5, 1e-12);
  EXPECT_NEAR(FilteredBox(5.0, 0.0, 0.1, 0.1), 0.0, 1e-12);
  EXPECT_NEAR(FilteredBox(0.05, 0.0, 0.1, 0.02), 1.0, 1e-12);
}

TEST(ProceduralTexture, ValueNoiseIsContinuousAndBounded) {
  double previous = ValueNoise(0.0, 0.3, 7);
  for (double x = 0.001; x < 20.0; x += 0.001) {
    const double v = ValueNoise(x, 0.3, 7);
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
    ASSERT_LT(std::abs(v - previous), 0.01) << x;
    previous = v;
  }
  EXPECT_NE(ValueNoise(3.3, 1.1, 7), ValueNoise(3.3, 1.1, 8));
}

TEST(ProceduralTexture, FbmFadesToItsMeanWhenThePixelIsLarge) {
  double sum = 0.0, sum_sq = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double v = FilteredFbm(0.37 * i, 0.11 * i, 0.0, 1.0, 4, 0.5, 3);
    sum += v;
    sum_sq += v * v;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.02);
  EXPECT_GT(sum_sq / n, 0.005);
  // Footprint above two wavelengths of the lowest octave: nothing left.
  EXPECT_EQ(FilteredFbm(3.7, 1.1, 1.0, 1.0, 4, 0.5, 3), 0.0);
  // Fine octaves fade first: less variance with a larger footprint.
  double fine = 0.0, coarse = 0.0;
  for (int i = 0; i < n; ++i) {
    fine += std::pow(FilteredFbm(0.37 * i, 0.11 * i, 0.0, 1.0, 5, 0.7, 3), 2);
    coarse += std::pow(FilteredFbm(0.37 * i, 0.11 * i, 0.1, 1.0, 5, 0.7, 3), 2);
  }
  EXPECT_LT(coarse, fine);
}

TEST(ProceduralTexture, LaneMarkingIsPaintedWhereItIs) {
  TextureContext context;
  context.markings.push_back({1.75, 0.12, 3.0, 6.0});
  SurfaceStyle asphalt;
  asphalt.material = Material::kAsphalt;
  asphalt.tint = {0.4f, 0.4f, 0.4f};
  TexelQuery on{1.0, 1.75, 0.01, 0.01};   // in a dash
  TexelQuery gap{5.0, 1.75, 0.01, 0.01};  // between dashes
  TexelQuery off{1.0, 0.5, 0.01, 0.01};
  const double paint = MaterialAlbedo(asphalt, on, context).g;
  EXPECT_GT(paint, 0.6);
  EXPECT_LT(MaterialAlbedo(asphalt, gap, context).g, 0.6);
  EXPECT_LT(MaterialAlbedo(asphalt, off, context).g, 0.6);
}

}  // namespace
}  // namespace roadscale::synth
