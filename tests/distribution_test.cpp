// Piecewise-constant 1D and 2D distributions: CDF inversion checked against the CDF written out here,
// densities that integrate to 1, zero-weight bins and rows, all-zero tables and the ends of [0,1).
#include "materials/sampling/distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace glossy::test {

namespace {

constexpr double kJustBelowOne = 1.0 - 1e-16;  // rounds to the largest double below 1

// P(X < x) for the piecewise-constant density of `f`, from its definition.
double cdfOf(const std::vector<double>& f, double x) {
  double total = 0.0, below = 0.0;
  for (double v : f) total += v;
  const double n = double(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double lo = double(i) / n, hi = double(i + 1) / n;
    below += f[i] * std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
  }
  return below / total;
}

}  // namespace

TEST(Distribution1D, SamplingInvertsTheCdfAndSkipsZeroBins) {
  const std::vector<double> f{1.0, 0.0, 3.0, 0.0, 4.0};
  const Distribution1D d(f);
  EXPECT_DOUBLE_EQ(d.integral(), 8.0 / 5.0);
  ASSERT_EQ(d.cdf().size(), 6u);
  EXPECT_EQ(d.cdf()[0], 0.0);
  EXPECT_EQ(d.cdf()[5], 1.0);

  for (int k = 0; k <= 1000; ++k) {
    const double u = k == 1000 ? kJustBelowOne : k / 1000.0;
    double pdf = -1.0;
    std::size_t bin = 99;
    const double x = d.sampleContinuous(u, &pdf, &bin);
    ASSERT_GE(x, 0.0);
    ASSERT_LT(x, 1.0);
    EXPECT_NEAR(cdfOf(f, x), u, 1e-12) << "u = " << u;
    EXPECT_EQ(bin, std::size_t(x * 5.0));
    EXPECT_GT(f[bin], 0.0) << "u = " << u << " landed in an empty bin";
    EXPECT_EQ(pdf, f[bin] / d.integral());
    EXPECT_EQ(d.pdf(x), pdf);
  }
  // A u exactly on the edge of an empty bin goes to the next non-empty one.
  std::size_t bin = 99;
  d.sampleContinuous(0.125, nullptr, &bin);
  EXPECT_EQ(bin, 2u);
  EXPECT_LT(d.sampleContinuous(1.0), 1.0);
  EXPECT_EQ(d.sampleContinuous(-0.5), 0.0);
}

TEST(Distribution1D, PdfIntegratesToOne) {
  const std::vector<double> f{0.5, 2.0, 0.0, 7.0, 1e-9, 3.0, 0.25};
  const Distribution1D d(f);
  const int n = 7000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += d.pdf((i + 0.5) / n) / n;
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_EQ(d.pdf(-0.1), 0.0);
  EXPECT_EQ(d.pdf(1.5), 0.0);
  EXPECT_EQ(d.pdf(1.0), d.pdf(0.99));
}

TEST(Distribution1D, DiscreteSamplingUsesBinMasses) {
  const Distribution1D d(std::vector<double>{1.0, 0.0, 3.0});
  double p = 0.0;
  EXPECT_EQ(d.sampleDiscrete(0.0, &p), 0u);
  EXPECT_DOUBLE_EQ(p, 0.25);
  EXPECT_EQ(d.sampleDiscrete(0.25, &p), 2u);
  EXPECT_DOUBLE_EQ(p, 0.75);
  EXPECT_EQ(d.sampleDiscrete(kJustBelowOne), 2u);
  EXPECT_EQ(d.discreteProbability(1), 0.0);
}

TEST(Distribution1D, AllZeroIsUniform) {
  const Distribution1D d(std::vector<double>(4, 0.0));
  EXPECT_EQ(d.integral(), 0.0);
  for (double u : {0.0, 0.3, 0.5, 0.9, kJustBelowOne}) {
    double pdf = 0.0;
    EXPECT_NEAR(d.sampleContinuous(u, &pdf), u, 1e-15);
    EXPECT_EQ(pdf, 1.0);
    EXPECT_EQ(d.pdf(u), 1.0);
  }
  EXPECT_DOUBLE_EQ(d.discreteProbability(3), 0.25);
}

TEST(Distribution1D, RejectsInvalidTables) {
  EXPECT_THROW(Distribution1D(std::vector<double>{}), std::invalid_argument);
  EXPECT_THROW(Distribution1D(std::vector<double>{1.0, -1.0}), std::invalid_argument);
  EXPECT_THROW(Distribution1D(std::vector<double>{1.0, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(Distribution1D(std::vector<double>{1.0, INFINITY}), std::invalid_argument);
}

namespace {

// 3 columns × 4 rows; row 2 is empty.
const std::vector<double> kTable{1.0, 2.0, 0.0,  //
                                 0.0, 0.0, 5.0,  //
                                 0.0, 0.0, 0.0,  //
                                 4.0, 1.0, 3.0};

}  // namespace

TEST(Distribution2D, SamplesFollowTheTableAndMatchPdf) {
  const Distribution2D d(kTable, 3, 4);
  EXPECT_DOUBLE_EQ(d.integral(), 16.0 / 12.0);
  // A stratified grid of u maps onto the cells in proportion to their weights.
  const int n = 600;
  std::vector<double> fraction(12, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto s = d.sample({(i + 0.5) / n, (j + 0.5) / n});
      ASSERT_GE(s.point.x, 0.0);
      ASSERT_LT(s.point.x, 1.0);
      ASSERT_GE(s.point.y, 0.0);
      ASSERT_LT(s.point.y, 1.0);
      const int cell = int(s.point.y * 4) * 3 + int(s.point.x * 3);
      ASSERT_GT(kTable[cell], 0.0);
      ASSERT_EQ(d.pdf(s.point), s.pdf);
      EXPECT_DOUBLE_EQ(s.pdf, kTable[cell] / d.integral());
      fraction[cell] += 1.0 / (double(n) * n);
    }
  for (int cell = 0; cell < 12; ++cell) EXPECT_NEAR(fraction[cell], kTable[cell] / 16.0, 2e-3) << "cell " << cell;
}

TEST(Distribution2D, PdfIntegratesToOne) {
  const Distribution2D d(kTable, 3, 4);
  const int n = 120;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) sum += d.pdf({(i + 0.5) / n, (j + 0.5) / n}) / (double(n) * n);
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_EQ(d.pdf({0.5, 0.6}), 0.0);  // the empty row
  EXPECT_EQ(d.pdf({-0.1, 0.5}), 0.0);
  EXPECT_EQ(d.pdf({0.5, 1.1}), 0.0);
}

TEST(Distribution2D, EndsOfTheUnitSquareGiveValidSamples) {
  const Distribution2D d(kTable, 3, 4);
  for (double a : {0.0, kJustBelowOne, 1.0})
    for (double b : {0.0, kJustBelowOne, 1.0}) {
      const auto s = d.sample({a, b});
      EXPECT_TRUE(std::isfinite(s.pdf) && s.pdf > 0.0);
      EXPECT_LT(s.point.x, 1.0);
      EXPECT_LT(s.point.y, 1.0);
      EXPECT_EQ(d.pdf(s.point), s.pdf);
    }
}

TEST(Distribution2D, AllZeroIsUniform) {
  const Distribution2D d(std::vector<double>(6, 0.0), 2, 3);
  const auto s = d.sample({0.3, 0.7});
  EXPECT_NEAR(s.point.x, 0.3, 1e-15);
  EXPECT_NEAR(s.point.y, 0.7, 1e-15);
  EXPECT_EQ(s.pdf, 1.0);
  EXPECT_EQ(d.pdf({0.9, 0.1}), 1.0);
  EXPECT_THROW(Distribution2D(std::vector<double>(5, 1.0), 2, 3), std::invalid_argument);
}

}  // namespace glossy::test
