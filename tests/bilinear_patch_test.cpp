// BilinearPatch, the warp that places an environment light's sample within its cell: a χ² test finds its
// samples distributed as the density it reports, for smooth, single-corner, half-black and very high-contrast
// patches; the density is the bilinear function over its mean; each coordinate's map is monotone (so
// stratified u stay stratified); the linear inversion is exact at its ends and in its degenerate cases.
#include "renderer/lights/bilinear_patch.h"
#include "tests/support/chi2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace glossy::test {

namespace {

const BilinearPatch kPatches[] = {
    {1.0, 2.0, 3.0, 4.0},        // smooth
    {0.0, 0.0, 0.0, 5.0},        // one lit corner: a bright texel beside dark ones
    {7.0, 0.0, 7.0, 0.0},        // black on the right
    {0.0, 0.0, 2.0, 1.0},        // black at the top
    {1e-6, 1.0, 1e3, 1e6},       // twelve orders of magnitude
    {3.0, 3.0, 3.0, 3.0},        // constant: uniform
};

std::string describe(const BilinearPatch& p) {
  return "patch (" + std::to_string(p.v00) + ", " + std::to_string(p.v10) + ", " + std::to_string(p.v01) + ", " +
         std::to_string(p.v11) + ")";
}

}  // namespace

// Bins on a 16 × 16 grid: the density is bilinear on each, so its integral there is the bin's area times
// its value at the bin's centre, exactly.
TEST(BilinearPatch, SamplesFollowTheDensityItReports) {
  constexpr int kBins = 16, kSamples = 400000;
  for (const BilinearPatch& patch : kPatches) {
    std::vector<double> observed(kBins * kBins, 0.0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uniform;
    for (int k = 0; k < kSamples; ++k) {
      const Vec2 p = patch.sample({uniform(rng), uniform(rng)});
      ASSERT_TRUE(p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0) << describe(patch);
      observed[std::size_t(std::min(int(p.y * kBins), kBins - 1) * kBins + std::min(int(p.x * kBins), kBins - 1))] += 1.0;
    }
    double chi2 = 0.0, pooledObserved = 0.0, pooledExpected = 0.0;
    int bins = 0;
    for (int j = 0; j < kBins; ++j)
      for (int i = 0; i < kBins; ++i) {
        const double expected = patch.density({(i + 0.5) / kBins, (j + 0.5) / kBins}) / (kBins * kBins) * kSamples;
        const double seen = observed[std::size_t(j * kBins + i)];
        if (expected < 5.0) {
          pooledObserved += seen;
          pooledExpected += expected;
          continue;
        }
        chi2 += (seen - expected) * (seen - expected) / expected;
        ++bins;
      }
    if (pooledExpected >= 5.0) {
      chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
      ++bins;
    } else {
      EXPECT_LT(pooledObserved, 10.0) << describe(patch) << ": samples where the density is all but 0";
    }
    const double p = chi2Survival(chi2, bins - 1);
    EXPECT_GT(p, 0.01) << describe(patch) << ": χ² = " << chi2 << " with " << bins - 1 << " degrees of freedom";
  }
}

TEST(BilinearPatch, DensityIsTheBilinearFunctionOverItsMean) {
  for (const BilinearPatch& patch : kPatches) {
    // The bilinear function's mean is its corners' mean, so the density integrates to 1 (midpoint rule,
    // exact for a bilinear function).
    double integral = 0.0;
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) integral += patch.density({(i + 0.5) / 8, (j + 0.5) / 8}) / 64.0;
    EXPECT_NEAR(integral, 1.0, 1e-12) << describe(patch);
    EXPECT_NEAR(patch.density({0.0, 0.0}), patch.v00 / patch.mean(), 1e-12) << describe(patch);
    EXPECT_NEAR(patch.density({1.0, 1.0}), patch.v11 / patch.mean(), 1e-12) << describe(patch);
  }
  const BilinearPatch black{};
  EXPECT_EQ(black.density({0.3, 0.6}), 1.0) << "a black patch is sampled uniformly";
  EXPECT_EQ(black.sample({0.3, 0.6}), Vec2(0.3, 0.6));
}

// y depends on u.y alone and grows with it; x grows with u.x at every u.y.
TEST(BilinearPatch, EachCoordinateIsMonotoneInItsOwnU) {
  for (const BilinearPatch& patch : kPatches) {
    for (int a = 0; a <= 20; ++a) {
      const double fixed = a / 20.0;
      Vec2 previousX = patch.sample({0.0, fixed}), previousY = patch.sample({fixed, 0.0});
      for (int b = 1; b <= 200; ++b) {
        const double u = b / 200.0;
        const Vec2 alongX = patch.sample({u, fixed}), alongY = patch.sample({fixed, u});
        ASSERT_GE(alongX.x, previousX.x) << describe(patch) << " at u = (" << u << ", " << fixed << ")";
        ASSERT_EQ(alongX.y, previousX.y) << describe(patch);
        ASSERT_GE(alongY.y, previousY.y) << describe(patch) << " at u = (" << fixed << ", " << u << ")";
        previousX = alongX;
        previousY = alongY;
      }
    }
  }
}

TEST(BilinearPatch, LinearInversionAtItsEndsAndInItsDegenerateCases) {
  for (double u : {0.0, 0.1, 0.5, 0.9, 1.0}) {
    EXPECT_DOUBLE_EQ(BilinearPatch::sampleLinear(u, 2.0, 2.0), u) << "a constant density";
    EXPECT_DOUBLE_EQ(BilinearPatch::sampleLinear(u, 0.0, 3.0), std::sqrt(u)) << "density ∝ t";
    EXPECT_NEAR(BilinearPatch::sampleLinear(u, 3.0, 0.0), 1.0 - std::sqrt(1.0 - u), 1e-15) << "density ∝ 1 − t";
    EXPECT_DOUBLE_EQ(BilinearPatch::sampleLinear(u, 0.0, 0.0), u) << "no density: anything valid";
  }
  // The CDF at the returned t is u, for a strongly sloped density.
  const double a = 1.0, b = 1e4;
  for (double u : {1e-12, 1e-6, 0.01, 0.3, 0.99, 1.0 - 1e-12}) {
    const double t = BilinearPatch::sampleLinear(u, a, b);
    EXPECT_NEAR((a * t + 0.5 * (b - a) * t * t) / (0.5 * (a + b)), u, 1e-12 * u) << "u = " << u;
  }
}

}  // namespace glossy::test
