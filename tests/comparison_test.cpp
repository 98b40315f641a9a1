// compareToMeasured on synthetic sheets: known images M and P_p; each replicate is the truth plus noise whose
// level varies over the image and which is correlated between the panels of a replicate like coherent
// renders (a component shared by all panels plus each panel's own); one panel's noise is heavy-tailed (rare
// large spikes, mean-corrected so its replicates stay unbiased). The error estimate must be unbiased where
// the plain figure is not, the intervals must cover the truth at their stated rate without being wide, and
// the verdict must name the closer model when the true errors differ and tie when they do not. The noise is
// comparable to the error per pixel, as in a sheet at moderate sample counts: the regime where an interval
// that overstates the noise (the replicate jackknife) covers far more than 95 %.
#include "renderer/sheet/comparison.h"

#include "materials/core/types.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace glossy::test {
namespace {

constexpr int kSize = 40;
constexpr size_t kPixels = size_t(kSize) * kSize;

using Image = std::vector<double>;  // RGB interleaved

// The object: a disc with a notch cut into it, so that pixels inside and around it are masked out.
std::vector<char> discMask() {
  std::vector<char> mask(kPixels);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double u = (x + 0.5) / kSize - 0.5, v = (y + 0.5) / kSize - 0.5;
      const bool notch = u > 0.15 && std::abs(v) < 0.07;
      mask[size_t(y) * kSize + x] = u * u + v * v < 0.44 * 0.44 && !notch;
    }
  return mask;
}

// The measured panel's truth: smooth, positive, different in each channel.
Image measuredTruth() {
  Image m(3 * kPixels);
  for (size_t i = 0; i < kPixels; ++i) {
    const double u = double(i % kSize) / kSize, v = double(i / kSize) / kSize;
    for (int c = 0; c < 3; ++c)
      m[3 * i + c] = (0.2 + 0.6 * (0.5 + 0.5 * std::sin(3.0 * u + 1.3 * c) * std::cos(2.0 * v))) * (1.0 - 0.2 * c);
  }
  return m;
}

// A model's truth: M with a relative error that varies over the image, plus a relative bias (which moves the
// luminance ratio away from 1).
Image modelTruth(const Image& m, double amplitude, double bias, double phase) {
  Image p(m.size());
  for (size_t i = 0; i < kPixels; ++i) {
    const double u = double(i % kSize) / kSize, v = double(i / kSize) / kSize;
    for (int c = 0; c < 3; ++c)
      p[3 * i + c] = m[3 * i + c] * (1.0 + bias + amplitude * std::sin(5.0 * u + phase) * std::cos(4.0 * v - 0.7 * c));
  }
  return p;
}

double squaredDistance(const Image& a, const Image& b, const std::vector<char>& mask) {
  double sum = 0.0;
  for (size_t i = 0; i < kPixels; ++i)
    if (mask[i])
      for (int c = 0; c < 3; ++c) sum += (a[3 * i + c] - b[3 * i + c]) * (a[3 * i + c] - b[3 * i + c]);
  return sum;
}

// The model scaled about M to a given true squared error.
Image withSquaredError(const Image& model, const Image& m, const std::vector<char>& mask, double target) {
  const double scale = std::sqrt(target / squaredDistance(model, m, mask));
  Image p(m.size());
  for (size_t k = 0; k < m.size(); ++k) p[k] = m[k] + scale * (model[k] - m[k]);
  return p;
}

// The noise of one panel: sd `level` at the noisiest pixels, less elsewhere; spikeSize > 0 adds, with the
// sheet's spike rate, a spike of that many sds (minus its mean, so the replicates stay unbiased).
struct Noise {
  double level;
  double spikeSize = 0.0;
};

struct Replicates {
  std::vector<std::vector<RgbImage>> models;
  std::vector<RgbImage> measured;
};

struct SyntheticSheet {
  std::vector<char> mask = discMask();
  Image measured = measuredTruth();
  std::vector<Image> models;
  Noise measuredNoise{0.08};
  std::vector<Noise> modelNoise;
  double correlation = 0.8;  // of the noise of the panels within one replicate
  double spikeRate = 0.01;

  double measuredSquared() const { return squaredDistance(measured, Image(measured.size(), 0.0), mask); }
  double squaredError(size_t p) const { return squaredDistance(models[p], measured, mask); }
  double relativeRmse(size_t p) const { return std::sqrt(squaredError(p) / measuredSquared()); }
  double luminanceRatio(size_t p) const {
    double a = 0.0, b = 0.0;
    for (size_t i = 0; i < kPixels; ++i)
      if (mask[i]) {
        a += luminance(Rgb(models[p][3 * i], models[p][3 * i + 1], models[p][3 * i + 2]));
        b += luminance(Rgb(measured[3 * i], measured[3 * i + 1], measured[3 * i + 2]));
      }
    return a / b;
  }

  Replicates render(int k, std::mt19937_64& rng) const {
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform;
    const auto truthImage = [](const Image& truth) {
      RgbImage image(kSize, kSize);
      for (size_t k = 0; k < truth.size(); ++k) image.pixels[k] = float(truth[k]);
      return image;
    };
    Replicates out;
    out.measured.assign(size_t(k), truthImage(measured));
    for (const Image& model : models) out.models.push_back(std::vector<RgbImage>(size_t(k), truthImage(model)));
    const double own = std::sqrt(1.0 - correlation * correlation);
    for (int j = 0; j < k; ++j)
      for (size_t i = 0; i < kPixels; ++i) {
        if (!mask[i]) continue;
        // Noisier towards the right and in a band: the noise level varies from pixel to pixel.
        const double u = double(i % kSize) / kSize, v = double(i / kSize) / kSize;
        const double profile = (0.4 + 0.6 * u) * (0.6 + 0.4 * std::cos(6.0 * v));
        // Render noise is largely common to the three channels.
        const double grey = normal(rng);
        double shared[3];
        for (double& s : shared) s = 0.6 * grey + 0.8 * normal(rng);
        const bool spike = uniform(rng) < spikeRate;
        const auto addNoise = [&](RgbImage& image, const Noise& noise) {
          const double sigma = noise.level * profile;
          const double spikeValue = noise.spikeSize * sigma * ((spike ? 1.0 : 0.0) - spikeRate);
          for (int c = 0; c < 3; ++c)
            image.pixels[3 * i + c] += float(sigma * (correlation * shared[c] + own * normal(rng)) + spikeValue);
        };
        addNoise(out.measured[j], measuredNoise);
        for (size_t p = 0; p < models.size(); ++p) addNoise(out.models[p][j], modelNoise[p]);
      }
    return out;
  }

  Comparison compare(int k, std::mt19937_64& rng) const {
    const Replicates r = render(k, rng);
    return compareToMeasured(r.models, r.measured, mask);
  }
};

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / double(v.size());
}
double sd(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0.0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / double(v.size() - 1));
}

// Three models, of different errors and noise: model 0 a clear error at moderate noise, model 1 a small
// error under strong noise (its noise dominates the error at most pixels), model 2 with heavy-tailed noise.
SyntheticSheet threeModels() {
  SyntheticSheet s;
  s.models = {modelTruth(s.measured, 0.15, 0.05, 0.0), modelTruth(s.measured, 0.08, -0.03, 1.0),
              modelTruth(s.measured, 0.12, 0.0, 2.0)};
  s.modelNoise = {{0.08}, {0.15}, {0.08, 12.0}};
  return s;
}

// 400 comparisons of the three-model sheet at K = 4, shared by the unbiasedness and coverage tests.
struct Campaign {
  static constexpr int kTrials = 400, kReplicates = 4;
  SyntheticSheet sheet = threeModels();
  std::vector<Comparison> comparisons;
  std::vector<double> plainSquaredError[3];  // Σ |p̄ − m̄|², noise included, per model

  Campaign() {
    std::mt19937_64 rng(20240611);
    for (int t = 0; t < kTrials; ++t) {
      const Replicates r = sheet.render(kReplicates, rng);
      comparisons.push_back(compareToMeasured(r.models, r.measured, sheet.mask));
      for (size_t p = 0; p < 3; ++p) {
        double sum = 0.0;
        for (size_t i = 0; i < kPixels; ++i)
          if (sheet.mask[i])
            for (int c = 0; c < 3; ++c) {
              double d = 0.0;
              for (int j = 0; j < kReplicates; ++j) d += (r.models[p][j].pixels[3 * i + c] - r.measured[j].pixels[3 * i + c]) / kReplicates;
              sum += d * d;
            }
        plainSquaredError[p].push_back(sum);
      }
    }
  }
  std::vector<double> figure(size_t p, double PanelFigures::*field) const {
    std::vector<double> v;
    for (const Comparison& c : comparisons) v.push_back(c.panels[p].*field);
    return v;
  }
};

const Campaign& campaign() {
  static const Campaign c;
  return c;
}

TEST(Comparison, SquaredErrorIsUnbiasedWhereThePlainFigureIsNot) {
  const Campaign& c = campaign();
  const double trials = Campaign::kTrials;
  for (size_t p = 0; p < 3; ++p) {
    SCOPED_TRACE("model " + std::to_string(p));
    const double truth = c.sheet.squaredError(p);
    const std::vector<double> a = c.figure(p, &PanelFigures::squaredError);
    const double standardError = sd(a) / std::sqrt(trials);
    EXPECT_NEAR(mean(a), truth, 4.0 * standardError);
    // The plain figure's noise term is many standard errors: a U-statistic that let it in would fail above.
    const std::vector<double>& plain = c.plainSquaredError[p];
    EXPECT_GT(mean(plain) - truth, 20.0 * standardError);
    const std::vector<double> noisy = c.figure(p, &PanelFigures::noisyRelativeRmse);
    EXPECT_GT(mean(noisy) - c.sheet.relativeRmse(p), 20.0 * sd(noisy) / std::sqrt(trials));
  }
  std::vector<double> b;
  for (const Comparison& comparison : c.comparisons) b.push_back(comparison.measuredSquared);
  EXPECT_NEAR(mean(b), c.sheet.measuredSquared(), 4.0 * sd(b) / std::sqrt(trials));
}

TEST(Comparison, IntervalsCoverAtTheirRateAndAreNotWide) {
  const Campaign& c = campaign();
  for (size_t p = 0; p < 3; ++p) {
    SCOPED_TRACE("model " + std::to_string(p));
    const double r = c.sheet.relativeRmse(p), l = c.sheet.luminanceRatio(p);
    int coveredR = 0, coveredL = 0;
    std::vector<double> halfWidths;
    for (const Comparison& comparison : c.comparisons) {
      const PanelFigures& f = comparison.panels[p];
      ASSERT_TRUE(f.hasCi);
      coveredR += f.relativeRmseCi.lo <= r && r <= f.relativeRmseCi.hi;
      coveredL += f.luminanceRatioCi.lo <= l && l <= f.luminanceRatioCi.hi;
      halfWidths.push_back(f.relativeRmseCi.halfWidth());
    }
    const double rateR = coveredR / double(Campaign::kTrials), rateL = coveredL / double(Campaign::kTrials);
    const double widthRatio = mean(halfWidths) / (1.959964 * sd(c.figure(p, &PanelFigures::relativeRmse)));
    std::printf("model %zu: r = %.4f, r* covered %.1f %%, luminance ratio covered %.1f %%, "
                "half-width / (1.96 sd of r*) = %.3f\n",
                p, r, 100.0 * rateR, 100.0 * rateL, widthRatio);
    // Model 2's rare spikes leave most draws fewer than 50 degrees of freedom, and those take the
    // test-inversion interval (comparison.cpp), which counts a spike in the variance it scales: about
    // twice as wide as the spread there. That is the price of intervals that hold on sharp highlights.
    const double widest = p == 2 ? 2.5 : 1.25;
    EXPECT_GE(rateR, 0.92);
    EXPECT_LE(rateR, p == 2 ? 1.0 : 0.98);
    EXPECT_GE(rateL, 0.92);
    EXPECT_LE(rateL, 0.98);
    EXPECT_GT(widthRatio, 1.0 / 1.25);
    EXPECT_LT(widthRatio, widest);
  }
  EXPECT_DOUBLE_EQ(c.comparisons.front().widestHalfWidth(),
                   std::max({c.comparisons.front().panels[0].relativeRmseCi.halfWidth(),
                             c.comparisons.front().panels[1].relativeRmseCi.halfWidth(),
                             c.comparisons.front().panels[2].relativeRmseCi.halfWidth()}));
}

// The share of draws whose r* interval holds the truth where `carriers` pixels carry the whole difference
// (1 + noise, noise a unit normal per replicate: per channel, or one draw for all three) and the other
// pixels of the 16 × 16 image agree exactly: ν is then a few units.
double coverageWhereAFewPixelsCarry(int carriers, bool perChannel, int draws, uint64_t seed) {
  constexpr int kSide = 16, kReplicates = 4;
  constexpr size_t kCount = size_t(kSide) * kSide;
  const std::vector<char> mask(kCount, 1);
  constexpr double kMeasured = 0.05;
  const double truth = std::sqrt(carriers / (kCount * kMeasured * kMeasured));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  int covered = 0;
  for (int draw = 0; draw < draws; ++draw) {
    std::vector<RgbImage> measured(kReplicates, RgbImage(kSide, kSide)), model = measured;
    for (int j = 0; j < kReplicates; ++j) {
      std::fill(measured[j].pixels.begin(), measured[j].pixels.end(), float(kMeasured));
      model[j] = measured[j];
      for (int p = 0; p < carriers; ++p) {
        const double d = 1.0 + normal(rng);
        for (int c = 0; c < 3; ++c) model[j].pixels[size_t(3 * p + c)] += float(perChannel && c > 0 ? 1.0 + normal(rng) : d);
      }
    }
    const PanelFigures f = compareToMeasured({model}, measured, mask).panels[0];
    EXPECT_TRUE(f.hasCi);
    covered += f.relativeRmseCi.lo <= truth && truth <= f.relativeRmseCi.hi;
  }
  return double(covered) / draws;
}

// A sharp highlight: one pixel carries the whole difference, and its replicates' noise is as large as the
// difference itself. An interval whose width is estimated at the draw's own difference shrinks with it
// where the difference comes out small (the delta method covers 83 % here); testing each candidate value
// with the variance it implies covers at the nominal rate.
TEST(Comparison, IntervalsHoldWhereOnePixelCarriesTheDifference) {
  const double covered = coverageWhereAFewPixelsCarry(1, true, 400, 7);
  std::printf("one pixel carries the difference: r covered %.1f %%\n", 100.0 * covered);
  EXPECT_GE(covered, 0.90);
}

// A few pixels carry the difference (ν about 3–10), each replicate's difference one draw for all three
// channels: ν is estimated from the same pixels' four replicates as the variance, and a draw whose pixels'
// replicates happen to agree gets a small variance and a larger ν at once. t at that ν falls short of the
// coverage asserted below; K − 1 = 3 degrees of freedom reach it.
TEST(Comparison, IntervalsHoldWhereAFewPixelsCarryTheDifference) {
  const double covered = coverageWhereAFewPixelsCarry(3, false, 1500, 11);
  std::printf("a few pixels carry the difference: r covered %.1f %%\n", 100.0 * covered);
  EXPECT_GE(covered, 0.955);
}

// A draw whose squared difference comes out further below 0 than its estimated noise allows (one pixel
// carries it, its replicates' differences one large and three slightly negative; the others agree
// exactly): the test inversion rejects every ρ ≥ 0, and the interval is [0, twice the noisy figure], not
// the empty [0, 0], which would claim r* = 0 exactly.
TEST(Comparison, ADifferenceBelowItsNoiseGivesNoEmptyInterval) {
  constexpr int kSide = 16, kReplicates = 4;
  const std::vector<char> mask(size_t(kSide) * kSide, 1);
  const float difference[kReplicates] = {1.49713f, -0.136993f, -0.0597632f, -0.0954585f};
  std::vector<RgbImage> measured(kReplicates, RgbImage(kSide, kSide)), model = measured;
  for (int j = 0; j < kReplicates; ++j) {
    std::fill(measured[j].pixels.begin(), measured[j].pixels.end(), 0.05f);
    model[j] = measured[j];
    for (int c = 0; c < 3; ++c) model[j].pixels[size_t(c)] += difference[j];
  }
  const PanelFigures f = compareToMeasured({model}, measured, mask).panels[0];
  ASSERT_TRUE(f.hasCi);
  EXPECT_TRUE(f.clamped);
  EXPECT_EQ(f.relativeRmseCi.lo, 0.0);
  EXPECT_GT(f.noisyRelativeRmse, 0.0);
  EXPECT_DOUBLE_EQ(f.relativeRmseCi.hi, 2.0 * f.noisyRelativeRmse);
}

// How often each outcome occurs over the trials: the closer model named alone, the other named alone, a tie.
struct VerdictRates {
  double named[3] = {}, tie = 0.0, inTie[3] = {};
};

VerdictRates verdictRates(const SyntheticSheet& sheet, int trials, uint64_t seed) {
  std::mt19937_64 rng(seed);
  VerdictRates rates;
  for (int t = 0; t < trials; ++t) {
    const Verdict v = sheet.compare(4, rng).verdict;
    if (v.models.size() == 1) rates.named[v.models.front()] += 1.0 / trials;
    if (v.models.size() > 1) {
      rates.tie += 1.0 / trials;
      for (size_t m : v.models) rates.inTie[m] += 1.0 / trials;
    }
  }
  return rates;
}

// Two models with similar error patterns whose true squared errors differ by 6 %, rendered coherently (noise
// correlation 0.97 between panels): the difference is clear once the correlation is accounted for.
TEST(Comparison, VerdictNamesTheCloserModel) {
  SyntheticSheet s;
  s.correlation = 0.97;
  const Image closer = modelTruth(s.measured, 0.10, 0.0, 0.5);
  s.models = {withSquaredError(modelTruth(s.measured, 0.10, 0.0, 0.7), s.measured, s.mask,
                               1.06 * squaredDistance(closer, s.measured, s.mask)),
              closer};
  s.modelNoise = {{0.10}, {0.10}};
  const VerdictRates rates = verdictRates(s, 200, 7);
  std::printf("clear difference: closer named %.1f %%, other named %.1f %%, tie %.1f %%\n", 100.0 * rates.named[1],
              100.0 * rates.named[0], 100.0 * rates.tie);
  EXPECT_GE(rates.named[1], 0.95);
  EXPECT_LT(rates.named[0], 0.02);
}

// Two models of equal true error (different error patterns) and a clearly worse third: a tie of the two, the
// worse one never in it.
TEST(Comparison, VerdictTiesEqualModels) {
  SyntheticSheet s;
  const Image first = modelTruth(s.measured, 0.10, 0.02, 0.5);
  const double error = squaredDistance(first, s.measured, s.mask);
  s.models = {first, withSquaredError(modelTruth(s.measured, 0.10, -0.02, 2.5), s.measured, s.mask, error),
              withSquaredError(modelTruth(s.measured, 0.10, 0.0, 4.0), s.measured, s.mask, 1.5 * error)};
  s.modelNoise = {{0.10}, {0.10}, {0.10}};
  const VerdictRates rates = verdictRates(s, 200, 11);
  std::printf("equal errors: tie %.1f %%, one named alone %.1f %%, worse one in a tie %.1f %%\n", 100.0 * rates.tie,
              100.0 * (rates.named[0] + rates.named[1]), 100.0 * rates.inTie[2]);
  EXPECT_GE(rates.tie, 0.90);
  EXPECT_LE(rates.named[0] + rates.named[1], 0.08);
  EXPECT_EQ(rates.named[2], 0.0);
  EXPECT_LT(rates.inTie[2], 0.02);
}

SyntheticSheet oneModel() {
  SyntheticSheet s;
  s.models = {modelTruth(s.measured, 0.15, 0.05, 0.0)};
  s.modelNoise = {{0.08}};
  return s;
}

TEST(Comparison, OneReplicateGivesOnlyThePlainFigures) {
  std::mt19937_64 rng(1);
  const Comparison c = oneModel().compare(1, rng);
  EXPECT_EQ(c.replicates, 1);
  EXPECT_TRUE(c.panels[0].compared);
  EXPECT_GT(c.panels[0].noisyRelativeRmse, 0.0);
  EXPECT_GT(c.panels[0].luminanceRatio, 0.0);
  EXPECT_FALSE(c.panels[0].available);
  EXPECT_FALSE(c.panels[0].hasCi);
  EXPECT_TRUE(c.verdict.models.empty());
  EXPECT_EQ(c.widestHalfWidth(), std::numeric_limits<double>::infinity());
}

TEST(Comparison, TwoOrThreeReplicatesGiveAnEstimateWithoutInterval) {
  const SyntheticSheet s = oneModel();
  for (int k : {2, 3}) {
    std::mt19937_64 rng(2);
    const Comparison c = s.compare(k, rng);
    EXPECT_TRUE(c.panels[0].available) << k;
    EXPECT_NEAR(c.panels[0].relativeRmse, s.relativeRmse(0), 0.3 * s.relativeRmse(0)) << k;
    EXPECT_FALSE(c.panels[0].hasCi) << k;
    EXPECT_TRUE(c.verdict.models.empty()) << k;
    EXPECT_EQ(c.verdict.why, "no verdict: fewer than 4 replicates");
    EXPECT_EQ(c.widestHalfWidth(), std::numeric_limits<double>::infinity());
  }
}

// P = M: the estimate straddles 0, so it clamps in about half the trials; the interval starts at 0 nearly
// always (it covers the true 0) and never below; r* stays well under the plain figure's noise floor.
TEST(Comparison, ExactMatchClampsAtZero) {
  SyntheticSheet s;
  s.models = {s.measured};
  s.modelNoise = {{0.10}};
  std::mt19937_64 rng(3);
  int clamped = 0, coversZero = 0;
  std::vector<double> r, noisy;
  constexpr int kTrials = 100;
  for (int t = 0; t < kTrials; ++t) {
    const PanelFigures f = s.compare(4, rng).panels[0];
    ASSERT_TRUE(f.hasCi);
    clamped += f.clamped;
    EXPECT_EQ(f.clamped, f.relativeRmse == 0.0);
    EXPECT_GE(f.relativeRmseCi.lo, 0.0);
    EXPECT_LE(f.relativeRmseCi.lo, f.relativeRmse);
    EXPECT_GE(f.relativeRmseCi.hi, f.relativeRmse);
    coversZero += f.relativeRmseCi.lo == 0.0;
    r.push_back(f.relativeRmse);
    noisy.push_back(f.noisyRelativeRmse);
  }
  EXPECT_GT(clamped, kTrials / 5);
  EXPECT_LT(clamped, 4 * kTrials / 5);
  EXPECT_GE(coversZero, 90);
  EXPECT_LT(mean(r), 0.4 * mean(noisy));
}

TEST(Comparison, EmptyMaskGivesNoFigures) {
  SyntheticSheet s = oneModel();
  std::mt19937_64 rng(4);
  const Replicates r = s.render(4, rng);
  const Comparison c = compareToMeasured(r.models, r.measured, std::vector<char>(kPixels, 0));
  EXPECT_EQ(c.pixels, 0u);
  EXPECT_FALSE(c.panels[0].compared);
  EXPECT_FALSE(c.panels[0].available);
  EXPECT_TRUE(c.verdict.models.empty());
  EXPECT_EQ(c.verdict.why, "no verdict: no pixels to compare");
  EXPECT_EQ(c.widestHalfWidth(), std::numeric_limits<double>::infinity());
}

TEST(Comparison, BlackMeasuredPanelGivesNoFigures) {
  SyntheticSheet s = oneModel();
  std::mt19937_64 rng(5);
  Replicates r = s.render(4, rng);
  for (RgbImage& image : r.measured) std::fill(image.pixels.begin(), image.pixels.end(), 0.0f);
  const Comparison c = compareToMeasured(r.models, r.measured, s.mask);
  EXPECT_GT(c.pixels, 0u);
  EXPECT_FALSE(c.panels[0].compared);
  EXPECT_FALSE(c.panels[0].available);
  EXPECT_TRUE(c.verdict.models.empty());
}

TEST(Comparison, NoMeasuredPanelGivesNoFigures) {
  SyntheticSheet s = oneModel();
  std::mt19937_64 rng(10);
  const Replicates r = s.render(4, rng);
  const Comparison c = compareToMeasured(r.models, {}, s.mask);
  EXPECT_EQ(c.replicates, 0);
  ASSERT_EQ(c.panels.size(), 1u);
  EXPECT_FALSE(c.panels[0].compared);
  EXPECT_TRUE(c.verdict.models.empty());
  EXPECT_EQ(c.verdict.why, "no verdict: no measured panel");
}

// A value that is not finite leaves its pixel out of every panel's figures, exactly as if it were unmasked.
TEST(Comparison, NonFinitePixelIsSkippedAndCounted) {
  SyntheticSheet s = threeModels();
  std::mt19937_64 rng(6);
  const Replicates clean = s.render(4, rng);
  const size_t bad = size_t(20) * kSize + 20, worse = size_t(30) * kSize + 15;
  ASSERT_TRUE(s.mask[bad] && s.mask[worse]);
  Replicates poisoned = clean;
  poisoned.models[1][2].pixels[3 * bad + 1] = std::numeric_limits<float>::quiet_NaN();
  poisoned.measured[0].pixels[3 * worse] = std::numeric_limits<float>::infinity();
  std::vector<char> without = s.mask;
  without[bad] = without[worse] = 0;

  const Comparison c = compareToMeasured(poisoned.models, poisoned.measured, s.mask);
  const Comparison expected = compareToMeasured(clean.models, clean.measured, without);
  EXPECT_EQ(c.skippedPixels, 2u);
  EXPECT_EQ(c.pixels, expected.pixels);
  EXPECT_EQ(c.measuredSquared, expected.measuredSquared);
  for (size_t p = 0; p < 3; ++p) {
    EXPECT_TRUE(std::isfinite(c.panels[p].relativeRmse));
    EXPECT_EQ(c.panels[p].squaredError, expected.panels[p].squaredError);
    EXPECT_EQ(c.panels[p].relativeRmseCi.hi, expected.panels[p].relativeRmseCi.hi);
    EXPECT_EQ(c.panels[p].luminanceRatio, expected.panels[p].luminanceRatio);
    EXPECT_EQ(c.panels[p].luminanceRatioCi.lo, expected.panels[p].luminanceRatioCi.lo);
  }
  EXPECT_EQ(c.verdict.models, expected.verdict.models);
}

TEST(Comparison, PanelWithoutImagesIsLeftOut) {
  SyntheticSheet s = oneModel();
  std::mt19937_64 rng(8);
  Replicates r = s.render(4, rng);
  r.models.insert(r.models.begin(), std::vector<RgbImage>{});
  const Comparison c = compareToMeasured(r.models, r.measured, s.mask);
  ASSERT_EQ(c.panels.size(), 2u);
  EXPECT_FALSE(c.panels[0].compared);
  EXPECT_TRUE(c.panels[1].hasCi);
  EXPECT_EQ(c.verdict.models, std::vector<size_t>{1});
}

TEST(Comparison, InconsistentInputsThrow) {
  SyntheticSheet s = oneModel();
  std::mt19937_64 rng(9);
  const Replicates r = s.render(4, rng);
  std::vector<std::vector<RgbImage>> fewer = r.models;
  fewer[0].pop_back();
  EXPECT_THROW(compareToMeasured(fewer, r.measured, s.mask), std::invalid_argument);
  std::vector<RgbImage> smaller = r.measured;
  smaller[1] = RgbImage(kSize, kSize - 1);
  EXPECT_THROW(compareToMeasured(r.models, smaller, s.mask), std::invalid_argument);
  EXPECT_THROW(compareToMeasured(r.models, r.measured, s.mask, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace glossy::test
