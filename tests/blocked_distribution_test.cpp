// BlockedDistribution2D: its samples follow the density it reports, the density integrates to 1 and
// follows the table to 16-bit quantisation, zero cells and rows are never drawn, the map from u is an
// inversion (monotone, so stratified u stay stratified), and partial blocks, all-zero tables and the ends
// of the square are handled.
#include "materials/sampling/blocked_distribution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace glossy::test {

namespace {

constexpr double kJustBelowOne = 1.0 - 1e-16;

// 75 columns (two full blocks and a partial one of 11) × 5 rows, with zero cells, a zero block, a zero row,
// a cell a million times fainter than its neighbours, and a bright spot.
std::vector<double> table(std::size_t width, std::size_t height) {
  std::vector<double> t(width * height);
  for (std::size_t y = 0; y < height; ++y)
    for (std::size_t x = 0; x < width; ++x) {
      double v = 1.0 + 0.5 * std::sin(0.3 * double(x) + double(y));
      if (x % 7 == 3) v = 0.0;
      if (y == 2) v = 0.0;
      if (y == 1 && x >= 32 && x < 64) v = 0.0;
      if (y == 3 && x == 40) v = 1e-6;
      if (y == 4 && x == 70) v = 500.0;
      t[y * width + x] = v;
    }
  return t;
}

constexpr std::size_t kWidth = 75, kHeight = 5;

}  // namespace

TEST(BlockedDistribution2D, DensityIntegratesToOneAndFollowsTheTable) {
  const std::vector<double> t = table(kWidth, kHeight);
  const BlockedDistribution2D d(t, kWidth, kHeight);
  double total = 0.0, sum = 0.0;
  for (double v : t) total += v;
  for (std::size_t y = 0; y < kHeight; ++y)
    for (std::size_t x = 0; x < kWidth; ++x) {
      const double density = d.cellDensity(x, y), weight = t[y * kWidth + x];
      sum += density / double(kWidth * kHeight);
      if (weight == 0.0) {
        EXPECT_EQ(density, 0.0) << x << ", " << y;
        continue;
      }
      EXPECT_GT(density, 0.0) << "a cell with weight must keep a density: " << x << ", " << y;
      const double exact = weight / total * double(kWidth * kHeight);
      // A share of a block is in 65535ths of it, one of them given to every child with weight before the
      // rest are shared out: off by at most 2 of them plus the number of children given one. Here a row is
      // two levels: cells in blocks of 32, and the row's 3 blocks in one.
      const auto massOf = [&](std::size_t from, std::size_t to) {
        double m = 0.0;
        for (std::size_t k = from; k < std::min(kWidth, to); ++k) m += t[y * kWidth + k];
        return m / total * double(kWidth * kHeight);
      };
      const double blockMass = massOf(x / 32 * 32, x / 32 * 32 + 32), rowMass = massOf(0, kWidth);
      const double cellShare = (2.0 + 32.0) * blockMass / 65535.0, blockShare = (2.0 + 3.0) * rowMass / 65535.0;
      EXPECT_NEAR(density, exact, cellShare + blockShare * exact / blockMass + 1e-12) << x << ", " << y;
    }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_EQ(d.pdf({0.5, 0.5}), 0.0);  // the zero row
  EXPECT_EQ(d.pdf({-0.1, 0.5}), 0.0);
  EXPECT_EQ(d.pdf({0.5, 1.1}), 0.0);
}

TEST(BlockedDistribution2D, SamplesFollowTheDensityItReports) {
  const std::vector<double> t = table(kWidth, kHeight);
  const BlockedDistribution2D d(t, kWidth, kHeight);
  // A stratified grid of u lands in each cell in proportion to its density.
  const int n = 1500;
  std::vector<double> fraction(kWidth * kHeight, 0.0), left(kWidth * kHeight, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto s = d.sample({(i + 0.5) / n, (j + 0.5) / n});
      ASSERT_TRUE(s.point.x >= 0.0 && s.point.x < 1.0 && s.point.y >= 0.0 && s.point.y < 1.0);
      ASSERT_EQ(s.column, std::size_t(s.point.x * kWidth));
      ASSERT_EQ(s.row, std::size_t(s.point.y * kHeight));
      ASSERT_GT(t[s.row * kWidth + s.column], 0.0) << "drew a cell without weight";
      fraction[s.row * kWidth + s.column] += 1.0 / (double(n) * n);
      // The density is constant within a cell: its left half gets half of it.
      if (s.point.x * kWidth - double(s.column) < 0.5) left[s.row * kWidth + s.column] += 1.0 / (double(n) * n);
    }
  for (std::size_t y = 0; y < kHeight; ++y) {
    double row = 0.0;  // the row's probability: the height of its cells' preimages in u
    for (std::size_t x = 0; x < kWidth; ++x) row += d.cellDensity(x, y) / double(kWidth * kHeight);
    for (std::size_t x = 0; x < kWidth; ++x) {
      const double expected = d.cellDensity(x, y) / double(kWidth * kHeight);
      // An inversion's preimage of a cell is a rectangle, row × expected / row in u, and a grid of n²
      // points counts a rectangle to within its sides' lengths in points (plus the corners).
      const double tolerance = row > 0.0 ? (row + expected / row) / n + 2.0 / (double(n) * n) : 0.0;
      EXPECT_NEAR(fraction[y * kWidth + x], expected, tolerance) << "cell " << x << ", " << y;
      EXPECT_NEAR(left[y * kWidth + x], expected / 2.0, tolerance) << "left half of cell " << x << ", " << y;
    }
  }
}

TEST(BlockedDistribution2D, IsAnInversionMonotoneInEachCoordinate) {
  const std::vector<double> t = table(kWidth, kHeight);
  const BlockedDistribution2D d(t, kWidth, kHeight);
  for (double uy : {0.05, 0.3, 0.61, 0.9}) {
    double last = -1.0;
    for (int i = 0; i <= 20000; ++i) {
      const double ux = i == 20000 ? kJustBelowOne : i / 20000.0;
      const auto s = d.sample({ux, uy});
      ASSERT_GE(s.point.x, last) << "ux = " << ux;
      last = s.point.x;
    }
  }
  double last = -1.0;
  for (int j = 0; j <= 5000; ++j) {
    const auto s = d.sample({0.5, j / 5000.0});
    ASSERT_GE(s.point.y, last);
    last = s.point.y;
  }
  // The faint cell, a millionth of its neighbours, keeps its one share of its block: some u in its row
  // draws it.
  double uy = 0.0;
  while (d.sample({0.5, uy}).row != 3) uy += 1e-3;
  int faint = 0;
  for (int i = 0; i < 2000000; ++i) {
    const auto s = d.sample({(i + 0.5) / 2000000.0, uy});
    ASSERT_EQ(s.row, 3u);
    if (s.column == 40) ++faint;
  }
  EXPECT_GT(faint, 0) << "a cell with weight was never drawn";
}

TEST(BlockedDistribution2D, BatchEqualsSingleSamples) {
  const std::vector<double> t = table(kWidth, kHeight);
  const BlockedDistribution2D d(t, kWidth, kHeight);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform;
  constexpr int n = BlockedDistribution2D::kMaxBatch;
  for (int round = 0; round < 200; ++round) {
    bool want[n];
    Vec2 u[n];
    for (int i = 0; i < n; ++i) {
      want[i] = (i + round) % 3 != 0;
      u[i] = {uniform(rng), uniform(rng)};
    }
    BlockedDistribution2D::Sample out[n];
    d.sample(want, u, out, n);
    for (int i = 0; i < n; ++i) {
      if (!want[i]) continue;
      const auto one = d.sample(u[i]);
      ASSERT_EQ(out[i].point, one.point);
      ASSERT_EQ(out[i].column, one.column);
      ASSERT_EQ(out[i].row, one.row);
    }
  }
}

TEST(BlockedDistribution2D, EndsOfTheSquareAndDegenerateTables) {
  const std::vector<double> t = table(kWidth, kHeight);
  const BlockedDistribution2D d(t, kWidth, kHeight);
  for (double a : {0.0, kJustBelowOne, 1.0, -1.0, std::nan("")})
    for (double b : {0.0, kJustBelowOne, 1.0}) {
      const auto s = d.sample({a, b});
      EXPECT_LT(s.point.x, 1.0);
      EXPECT_LT(s.point.y, 1.0);
      EXPECT_GT(d.cellDensity(s.column, s.row), 0.0) << a << ", " << b;
    }

  // All zero: uniform, to the quantisation of the shares (a cell's of its block of 32 is 2048 ± 1
  // 65535ths, 1/2048 of itself, and its block's of the row is off by a few 65535ths more).
  const BlockedDistribution2D zero(std::vector<double>(40 * 3, 0.0), 40, 3);
  for (std::size_t y = 0; y < 3; ++y)
    for (std::size_t x = 0; x < 40; ++x) EXPECT_NEAR(zero.cellDensity(x, y), 1.0, 1.0 / 2048.0 + 4.0 / 65535.0);
  const auto s = zero.sample({0.3, 0.7});
  EXPECT_NEAR(s.point.x, 0.3, 1e-4);
  EXPECT_NEAR(s.point.y, 0.7, 1e-15);

  // One column, one row.
  const BlockedDistribution2D single(std::vector<double>{2.0}, 1, 1);
  EXPECT_DOUBLE_EQ(single.cellDensity(0, 0), 1.0);
  EXPECT_NEAR(single.sample({0.25, 0.5}).point.x, 0.25, 1e-4);

  EXPECT_THROW(BlockedDistribution2D(std::vector<double>(5, 1.0), 2, 3), std::invalid_argument);
  EXPECT_THROW(BlockedDistribution2D(std::vector<double>{1.0, -1.0}, 2, 1), std::invalid_argument);
  EXPECT_THROW(BlockedDistribution2D(std::vector<double>{1.0, INFINITY}, 2, 1), std::invalid_argument);
}

// 2100 columns: a row is three levels deep (66 blocks of cells, 3 blocks of those, one top block).
TEST(BlockedDistribution2D, WideRowsAreDeeperTreesOfTheSameKind) {
  constexpr std::size_t width = 2100, height = 3;
  std::vector<double> t(width * height);
  for (std::size_t i = 0; i < t.size(); ++i)
    t[i] = i % 11 == 0 ? 0.0 : 1.0 + std::sin(0.01 * double(i)) + (i % 700 == 5 ? 300.0 : 0.0);
  const BlockedDistribution2D d(t, width, height);
  double sum = 0.0;
  for (std::size_t y = 0; y < height; ++y)
    for (std::size_t x = 0; x < width; ++x) {
      sum += d.cellDensity(x, y) / double(width * height);
      EXPECT_EQ(d.cellDensity(x, y) > 0.0, t[y * width + x] > 0.0) << x << ", " << y;
    }
  EXPECT_NEAR(sum, 1.0, 1e-12);

  // Per block of 32 cells, a stratified grid of u lands as the density says (the preimage of a block of
  // a row is a rectangle in u, so the counting error is bounded by its sides, as above).
  const int n = 1200;
  std::vector<double> fraction(height * 66, 0.0);
  double last = -1.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto s = d.sample({(i + 0.5) / n, (j + 0.5) / n});
      ASSERT_LT(s.column, width);
      ASSERT_GT(t[s.row * width + s.column], 0.0);
      ASSERT_EQ(d.pdf(s.point), d.cellDensity(s.column, s.row));
      if (i > 0) {
        ASSERT_GE(s.point.x, last);
      }
      last = s.point.x;
      fraction[s.row * 66 + s.column / 32] += 1.0 / (double(n) * n);
    }
  for (std::size_t y = 0; y < height; ++y) {
    double row = 0.0;
    for (std::size_t x = 0; x < width; ++x) row += d.cellDensity(x, y) / double(width * height);
    for (std::size_t b = 0; b < 66; ++b) {
      double expected = 0.0;
      for (std::size_t x = b * 32; x < std::min(width, b * 32 + 32); ++x)
        expected += d.cellDensity(x, y) / double(width * height);
      EXPECT_NEAR(fraction[y * 66 + b], expected, (row + expected / row) / n + 2.0 / (double(n) * n)) << b << ", " << y;
    }
  }
}

}  // namespace glossy::test
