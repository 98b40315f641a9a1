// The sheets' error maps (renderer/sheet/error_maps.h): the relative difference is the formula, masked and
// floored; the ꟻLIP figure's jackknife takes out most of the bias render noise adds, and its interval covers
// the noise-free ꟻLIP about as often as it says; ΔE_ITP's and SSIM's, treated alike, cover their means.
#include "renderer/image/delta_e_itp.h"
#include "renderer/image/flip.h"
#include "renderer/image/masked_mean.h"
#include "renderer/image/ssim.h"
#include "renderer/sheet/error_maps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace glossy::test {

namespace {

// A lit ball on a dim backdrop: smooth shading with one highlight several stops above 1.
RgbImage ball(int size, double brightness, double highlight) {
  RgbImage image(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size - 0.5, v = (y + 0.5) / size - 0.5, r2 = u * u + v * v;
      double value = 0.05;
      if (r2 < 0.16) value = brightness * (0.2 + std::sqrt(0.16 - r2)) + highlight * std::exp(-((u + 0.1) * (u + 0.1) + (v + 0.1) * (v + 0.1)) / 0.002);
      float* p = image.at(x, y);
      p[0] = float(value), p[1] = float(0.8 * value), p[2] = float(0.6 * value);
    }
  return image;
}

std::vector<char> ballMask(int size) {
  std::vector<char> mask(size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size - 0.5, v = (y + 0.5) / size - 0.5;
      mask[size_t(y) * size + x] = u * u + v * v < 0.16;
    }
  return mask;
}

// K replicates of `image`, each with its own multiplicative noise of relative spread `noise`.
std::vector<RgbImage> replicates(const RgbImage& image, int k, double noise, std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, noise);
  std::vector<RgbImage> out(size_t(k), image);
  for (RgbImage& r : out)
    for (size_t i = 0; i < r.pixels.size(); i += 3) {
      const double f = std::max(0.0, 1.0 + n(rng));
      for (int c = 0; c < 3; ++c) r.pixels[i + size_t(c)] = float(r.pixels[i + size_t(c)] * f);
    }
  return out;
}

}  // namespace

TEST(ErrorMaps, RelativeDifferenceIsTheFormulaOnTheObjectAndZeroElsewhere) {
  RgbImage m(3, 1), p(3, 1);
  const float mv[3][3] = {{1, 1, 1}, {0, 0, 0}, {2, 2, 2}}, pv[3][3] = {{1.5f, 1.5f, 1.5f}, {0.1f, 0.1f, 0.1f}, {7, 7, 7}};
  for (int x = 0; x < 3; ++x)
    for (int c = 0; c < 3; ++c) m.at(x, 0)[c] = mv[x][c], p.at(x, 0)[c] = pv[x][c];
  const std::vector<char> mask = {1, 1, 0};
  const ErrorMaps maps = errorMaps({p, p, p, p}, {m, m, m, m}, mask);
  ASSERT_TRUE(maps.available);
  ASSERT_EQ(maps.relativeDifference.size(), 3u);
  EXPECT_NEAR(maps.relativeDifference[0], 0.5, 1e-6);
  // Black measured pixel: the floor is 1 % of the object's mean measured luminance, (1 + 0) / 2.
  EXPECT_NEAR(maps.relativeDifference[1], 0.1 / 0.005, 1e-4);
  EXPECT_EQ(maps.relativeDifference[2], 0.0f) << "off the object";
  EXPECT_EQ(maps.flipMap.size(), 3u);
}

TEST(ErrorMaps, NoLightOnTheObjectGivesNoMaps) {
  const RgbImage black(8, 8), grey = ball(8, 1.0, 0.0);
  EXPECT_FALSE(errorMaps({grey, grey}, {black, black}, std::vector<char>(64, 1)).available);
  EXPECT_FALSE(errorMaps({grey, grey}, {grey, grey}, std::vector<char>(64, 0)).available);
  EXPECT_THROW(errorMaps({grey}, {grey, grey}, std::vector<char>(64, 1)), std::invalid_argument);
}

// Render noise raises ꟻLIP, so the sheet reports it as rendered, with the noise's spread: the jackknife
// interval over four replicates covers the figure's mean at that noise level about as often as it says,
// and the noise floor (two halves of the measured panel) is positive, below a real difference.
TEST(ErrorMaps, FlipsJackknifeIntervalCoversItsMeanOverRenders) {
  const int size = 48, trials = 80;
  const double noise = 0.3;  // coverage 0.95–0.96 also at 0.05 and 0.5
  const RgbImage truthM = ball(size, 1.0, 8.0), truthP = ball(size, 1.15, 5.0);
  const std::vector<char> mask = ballMask(size);
  const double noiseFree = maskedMean(hdrFlip(truthM, truthP).error, mask);
  std::mt19937 rng(7);
  std::vector<ErrorMaps> runs;
  double mean = 0.0, floor = 0.0;
  for (int t = 0; t < trials; ++t) {
    const std::vector<RgbImage> m = replicates(truthM, 4, noise, rng);
    runs.push_back(errorMaps(replicates(truthP, 4, noise, rng), m, mask));
    ASSERT_TRUE(runs.back().available && runs.back().hasCi);
    mean += runs.back().flip / trials;
    floor += flipNoiseFloor(m, mask) / trials;
  }
  int covered = 0;
  for (const ErrorMaps& r : runs) covered += r.flipCi.lo <= mean && mean <= r.flipCi.hi;
  RecordProperty("coverage", std::to_string(double(covered) / trials));
  EXPECT_GT(mean, noiseFree) << "noise raises ꟻLIP";
  EXPECT_GT(floor, 0.0);
  EXPECT_LT(floor, noiseFree) << "this much noise is smaller than the two images' difference";
  EXPECT_GE(covered, int(0.88 * trials)) << "of " << trials << "; mean " << mean << ", noise-free " << noiseFree;
  EXPECT_LE(covered, trials);
}

// ΔE_ITP and SSIM are treated as ꟻLIP is: the figure of the mean images, raised (ΔE_ITP) or lowered (SSIM)
// by noise, with a jackknife interval over the replicates that covers the figure's mean over renders
// about as often as it says.
TEST(ErrorMaps, DisplayFiguresJackknifeIntervalsCoverTheirMeansOverRenders) {
  const int size = 48, trials = 80;
  const double noise = 0.3;
  const RgbImage truthM = ball(size, 0.4, 3.0), truthP = ball(size, 0.46, 2.0);
  const std::vector<char> mask = ballMask(size);
  const double freeDelta = maskedMean(deltaEItpMap(truthM, truthP), mask), freeSsim = maskedMean(ssimMap(truthM, truthP), mask);
  std::mt19937 rng(11);
  std::vector<ErrorMaps> runs;
  double delta = 0.0, ssim = 0.0;
  for (int t = 0; t < trials; ++t) {
    runs.push_back(errorMaps(replicates(truthP, 4, noise, rng), replicates(truthM, 4, noise, rng), mask));
    ASSERT_TRUE(runs.back().available && runs.back().hasCi);
    delta += runs.back().deltaEItp / trials;
    ssim += runs.back().ssim / trials;
  }
  int coveredDelta = 0, coveredSsim = 0;
  for (const ErrorMaps& r : runs) {
    coveredDelta += r.deltaEItpCi.lo <= delta && delta <= r.deltaEItpCi.hi;
    coveredSsim += r.ssimCi.lo <= ssim && ssim <= r.ssimCi.hi;
    EXPECT_TRUE(r.deltaEItpCi.lo <= r.deltaEItp && r.deltaEItp <= r.deltaEItpCi.hi);
    EXPECT_TRUE(r.ssimCi.lo <= r.ssim && r.ssim <= r.ssimCi.hi);
  }
  RecordProperty("coverage_delta_e_itp", std::to_string(double(coveredDelta) / trials));
  RecordProperty("coverage_ssim", std::to_string(double(coveredSsim) / trials));
  EXPECT_GT(delta, freeDelta) << "noise raises ΔE_ITP";
  EXPECT_LT(ssim, freeSsim) << "noise lowers SSIM";
  EXPECT_GE(coveredDelta, int(0.88 * trials)) << "ΔE_ITP: mean " << delta << ", noise-free " << freeDelta;
  EXPECT_GE(coveredSsim, int(0.88 * trials)) << "SSIM: mean " << ssim << ", noise-free " << freeSsim;
}

}  // namespace glossy::test
