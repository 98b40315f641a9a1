// ΔE_ITP and SSIM of display-encoded images (renderer/image/delta_e_itp.h, renderer/image/ssim.h): their
// properties, hand-checked values, and the validation against colour-science and scikit-image
// (tests/display_metrics/reference_display_metrics.py in the test Python, which scripts/test-tools makes;
// the validation skips, saying so, without it).
#include "renderer/image/delta_e_itp.h"
#include "renderer/image/ssim.h"
#include "tests/support/test_python.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace glossy::test {

namespace {

RgbImage uniform(int w, int h, float r, float g, float b) {
  RgbImage image(w, h);
  for (size_t i = 0; i < image.pixels.size(); i += 3) image.pixels[i] = r, image.pixels[i + 1] = g, image.pixels[i + 2] = b;
  return image;
}

// A shaded ball with a highlight above the display's white, on a dim backdrop, with noise of relative
// spread `noise` drawn from `seed`.
RgbImage ball(int w, int h, double tint, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, noise);
  RgbImage image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u = (x + 0.5) / w - 0.5, v = (y + 0.5) / h - 0.5, r2 = u * u + v * v;
      double value = 0.02;
      if (r2 < 0.16) value = 0.6 * (0.1 + std::sqrt(0.16 - r2)) + 4.0 * std::exp(-((u + 0.1) * (u + 0.1) + (v + 0.1) * (v + 0.1)) / 0.003);
      float* p = image.at(x, y);
      const double f = std::max(0.0, 1.0 + n(rng));
      p[0] = float(value * f), p[1] = float(0.8 * value * f * tint), p[2] = float(0.5 * value * f);
    }
  return image;
}

double mean(const std::vector<float>& v) {
  double s = 0.0;
  for (float x : v) s += x;
  return s / double(v.size());
}

}  // namespace

TEST(DisplayMetrics, IdenticalImagesAreZeroApartAndFullySimilar) {
  const RgbImage a = ball(32, 24, 1.0, 0.1, 1);
  for (float d : deltaEItpMap(a, a)) EXPECT_EQ(d, 0.0f);
  for (float s : ssimMap(a, a)) EXPECT_NEAR(s, 1.0f, 1e-6f);
}

// Values worked from BT.2100 and BT.2124: white and mid-grey on the display are 100 and 50.05 cd/m²; the
// LMS of a grey equal its value (each matrix row sums to 1), so I = PQ(Y / 10000) and Ct = Cp = 0. The PQ
// curve itself is checked at its well-known points (100 cd/m² → 0.5081, 1000 cd/m² → 0.7518).
TEST(DisplayMetrics, DeltaEItpOfTwoGreysIsTheirPqDistance) {
  const auto pq = [](double cd) {
    const double m1 = 2610.0 / 16384, m2 = 2523.0 / 4096 * 128, c1 = 3424.0 / 4096, c2 = 2413.0 / 4096 * 32, c3 = 2392.0 / 4096 * 32;
    const double y = std::pow(cd / 10000.0, m1);
    return std::pow((c1 + c2 * y) / (1.0 + c3 * y), m2);
  };
  EXPECT_NEAR(pq(100.0), 0.5081, 1e-4);
  EXPECT_NEAR(pq(1000.0), 0.7518, 1e-4);
  const double expected = 720.0 * (pq(100.0) - pq(50.05));
  const std::vector<float> d = deltaEItpMap(uniform(2, 2, 1.0f, 1.0f, 1.0f), uniform(2, 2, 0.5f, 0.5f, 0.5f));
  for (float v : d) EXPECT_NEAR(v, expected, 1e-4 * expected);
}

// What the display cannot show does not count: above white and below black every value looks alike, and
// NaN shows as black.
TEST(DisplayMetrics, WhatTheDisplayClipsIsNotADifference) {
  EXPECT_EQ(deltaEItpMap(uniform(4, 4, 1.0f, 1.0f, 1.0f), uniform(4, 4, 9.0f, 2.0f, 1.5f))[5], 0.0f);
  EXPECT_EQ(deltaEItpMap(uniform(4, 4, 0.0f, 0.0f, 0.0f), uniform(4, 4, -3.0f, -0.1f, 0.0f))[5], 0.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(deltaEItpMap(uniform(4, 4, 0.0f, 0.0f, 0.0f), uniform(4, 4, nan, nan, nan))[0], 0.0f);
  for (float s : ssimMap(uniform(12, 12, 0.0f, 0.0f, 0.0f), uniform(12, 12, nan, -1.0f, 0.0f))) EXPECT_NEAR(s, 1.0f, 1e-6f);
  EXPECT_THROW(deltaEItpMap(RgbImage(2, 2), RgbImage(3, 2)), std::invalid_argument);
  EXPECT_THROW(ssimMap(RgbImage(2, 2), RgbImage(2, 3)), std::invalid_argument);
}

// More difference reads as more: ΔE_ITP grows and SSIM falls with the noise added to an image.
TEST(DisplayMetrics, MoreNoiseIsFartherAndLessSimilar) {
  const RgbImage clean = ball(48, 48, 1.0, 0.0, 1);
  double lastDelta = 0.0, lastSsim = 1.0;
  for (double noise : {0.02, 0.1, 0.4}) {
    const RgbImage noisy = ball(48, 48, 1.0, noise, 2);
    const double delta = mean(deltaEItpMap(clean, noisy)), ssim = mean(ssimMap(clean, noisy));
    EXPECT_GT(delta, lastDelta) << noise;
    EXPECT_LT(ssim, lastSsim) << noise;
    lastDelta = delta, lastSsim = ssim;
  }
}


// The validation: every pixel of both maps against colour-science's RGB_to_ICtCp and delta_E_ITP and
// scikit-image's structural_similarity (gaussian_weights, sigma 1.5, use_sample_covariance False), on
// images with highlights above white, negative and NaN pixels, colour shifts, blur and noise, and a
// non-square size (the mirrored borders).
TEST(DisplayMetricsReference, MatchesColourScienceAndScikitImage) {
  if (!std::filesystem::exists(testPython()))
    GTEST_SKIP() << "the test Python " << testPython() << " is absent (scripts/test-tools creates it)";
  TempDir tmp;
  if (const ScriptRun check = runTestPython(tmp, "tests/display_metrics/reference_display_metrics.py", {"--check"}); check.status != 0)
    GTEST_SKIP() << "colour-science or scikit-image is not importable by " << testPython() << ": " << check.err;

  const int w = 61, h = 40;
  const RgbImage base = ball(w, h, 1.0, 0.0, 1);
  RgbImage hostile = ball(w, h, 1.0, 0.2, 3);
  hostile.pixels[5] = -2.0f, hostile.pixels[100] = std::numeric_limits<float>::quiet_NaN(), hostile.pixels[301] = 1e30f;
  const std::vector<std::pair<RgbImage, RgbImage>> pairs = {
      {base, ball(w, h, 1.0, 0.05, 2)}, {base, ball(w, h, 1.2, 0.0, 1)}, {base, hostile}, {ball(w, h, 0.7, 0.3, 4), base}};
  std::vector<std::string> args = {std::to_string(w), std::to_string(h)};
  for (size_t i = 0; i < pairs.size(); ++i) {
    const std::string stem = (tmp / ("pair" + std::to_string(i))).string();
    writeFloats(stem + "_ref.f32", pairs[i].first.pixels);
    writeFloats(stem + "_test.f32", pairs[i].second.pixels);
    for (const char* s : {"_ref.f32", "_test.f32", "_de.f32", "_ssim.f32"}) args.push_back(stem + s);
  }
  const ScriptRun run = runTestPython(tmp, "tests/display_metrics/reference_display_metrics.py", args);
  ASSERT_EQ(run.status, 0) << run.err;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const std::string stem = (tmp / ("pair" + std::to_string(i))).string();
    const std::vector<float> delta = deltaEItpMap(pairs[i].first, pairs[i].second), ssim = ssimMap(pairs[i].first, pairs[i].second);
    const std::vector<float> theirDelta = readFloats(stem + "_de.f32", delta.size()), theirSsim = readFloats(stem + "_ssim.f32", ssim.size());
    double worstDelta = 0.0, worstSsim = 0.0;
    for (size_t j = 0; j < delta.size(); ++j) {
      worstDelta = std::max(worstDelta, std::fabs(double(delta[j]) - theirDelta[j]) / std::max(1.0, double(theirDelta[j])));
      worstSsim = std::max(worstSsim, std::fabs(double(ssim[j]) - theirSsim[j]));
    }
    EXPECT_LT(worstDelta, 1e-4) << "pair " << i << ": ΔE_ITP, relative above 1";
    EXPECT_LT(worstSsim, 1e-5) << "pair " << i << ": SSIM";
    std::printf("pair %zu: mean ΔE_ITP %.4f (colour-science %.4f), mean SSIM %.5f (scikit-image %.5f); worst pixel %.1e, %.1e\n", i,
                mean(delta), mean(theirDelta), mean(ssim), mean(theirSsim), worstDelta, worstSsim);
  }
}

}  // namespace glossy::test
