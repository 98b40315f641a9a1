// The environment's compact tables (renderer/lights/compact_cdf.h, nested_grid.h): shares that sum to
// one, a share for every child with weight however faint, none for the others, and draws that land in
// each child exactly as often as its share says.
#include "renderer/lights/compact_cdf.h"
#include "renderer/lights/nested_grid.h"
#include "tests/support/chi2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace glossy::test {

namespace {

// Weights with zeros at the ends and inside, a child 1e-12 of the total and one that dominates.
const std::vector<double> kWeights = {0.0, 3.0, 1e-12, 0.0, 7.5, 0.25, 1e6, 2.0, 0.0};

template <class T>
void expectSharesFollowTheWeights() {
  std::vector<T> cdf(kWeights.size());
  const double total = compact_cdf::build(kWeights.data(), kWeights.size(), cdf.data());
  EXPECT_DOUBLE_EQ(total, 1e6 + 12.75 + 1e-12);
  double sum = 0.0;
  for (std::size_t k = 0; k < kWeights.size(); ++k) {
    const double share = compact_cdf::share(cdf.data(), k);
    sum += share;
    if (kWeights[k] > 0.0) {
      EXPECT_GT(share, 0.0) << "child " << k << " has weight but no share";
    } else {
      EXPECT_EQ(share, 0.0) << "child " << k << " has no weight but a share";
    }
  }
  EXPECT_DOUBLE_EQ(sum, 1.0);

  // Every u lands in a child with a share, at a position in [0, 1) within it, and the map is monotone.
  std::size_t previous = 0;
  for (int i = 0; i < 100000; ++i) {
    double u = (i + 0.5) / 100000.0;
    const std::size_t child = compact_cdf::sample(cdf.data(), cdf.size(), u);
    ASSERT_GT(compact_cdf::share(cdf.data(), child), 0.0);
    ASSERT_TRUE(u >= 0.0 && u < 1.0);
    ASSERT_GE(child, previous);
    previous = child;
  }
  for (double u : {0.0, 1.0 - 0x1p-53, 1.0}) {
    double v = u;
    const std::size_t child = compact_cdf::sample(cdf.data(), cdf.size(), v);
    EXPECT_GT(compact_cdf::share(cdf.data(), child), 0.0) << u;
    EXPECT_TRUE(v >= 0.0 && v < 1.0) << u;
  }
}

template <class T>
void expectZerosDrawUniformly() {
  const std::vector<double> zeros(5, 0.0);
  std::vector<T> cdf(zeros.size());
  EXPECT_EQ(compact_cdf::build(zeros.data(), zeros.size(), cdf.data()), 0.0);
  for (std::size_t k = 0; k < zeros.size(); ++k) EXPECT_NEAR(compact_cdf::share(cdf.data(), k), 0.2, 1e-4);
}

}  // namespace

TEST(CompactCdf, FloatSharesFollowTheWeights) { expectSharesFollowTheWeights<float>(); }
TEST(CompactCdf, SixteenBitSharesFollowTheWeights) { expectSharesFollowTheWeights<uint16_t>(); }
TEST(CompactCdf, AllZerosDrawUniformly) {
  expectZerosDrawUniformly<float>();
  expectZerosDrawUniformly<uint16_t>();
}

// A grid of 13 × 7 patches in 4 × 3 cells (uneven splits): each cell's patch probabilities sum to one,
// follow the weights (up to the tables' rounding), and a χ² test finds the draws distributed as they say.
TEST(NestedGrid, PatchesAreDrawnWithinTheirCellAsTheTablesSay) {
  constexpr std::size_t kWidth = 13, kHeight = 7;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform;
  std::vector<double> weight(kWidth * kHeight);
  for (double& w : weight) w = uniform(rng) < 0.2 ? 0.0 : std::exp(6.0 * uniform(rng));
  const NestedGrid grid(kWidth, kHeight, 4, 3, [&](std::size_t row, std::span<double> out) {
    for (std::size_t c = 0; c < kWidth; ++c) out[c] = weight[row * kWidth + c];
  });
  ASSERT_EQ(grid.cellColumns(), 4u);
  ASSERT_EQ(grid.cellRows(), 3u);
  for (std::size_t cr = 0; cr < 3; ++cr)
    for (std::size_t cc = 0; cc < 4; ++cc) {
      double sum = 0.0, cellWeight = 0.0;
      for (std::size_t row = grid.rowStart(cr); row < grid.rowStart(cr + 1); ++row)
        for (std::size_t column = grid.columnStart(cc); column < grid.columnStart(cc + 1); ++column) {
          ASSERT_EQ(grid.cellOfColumn(column), cc);
          ASSERT_EQ(grid.cellOfRow(row), cr);
          sum += grid.probabilityInCell(column, row);
          cellWeight += weight[row * kWidth + column];
        }
      EXPECT_NEAR(sum, 1.0, 1e-12);
      EXPECT_NEAR(grid.cellWeight(cc, cr), cellWeight, 1e-9 * cellWeight);
      for (std::size_t row = grid.rowStart(cr); row < grid.rowStart(cr + 1) && cellWeight > 0.0; ++row)
        for (std::size_t column = grid.columnStart(cc); column < grid.columnStart(cc + 1); ++column) {
          const double w = weight[row * kWidth + column] / cellWeight;
          EXPECT_NEAR(grid.probabilityInCell(column, row), w, 1e-3 * w + 1e-4);
        }

      // χ² of 20000 draws in the cell against probabilityInCell, pooling patches expected below 5.
      const int n = 20000;
      std::vector<double> observed(kWidth * kHeight, 0.0);
      for (int i = 0; i < n; ++i) {
        Vec2 u(uniform(rng), uniform(rng));
        const NestedGrid::Patch p = grid.sample(cc, cr, u);
        ASSERT_EQ(grid.cellOfColumn(p.column), cc);
        ASSERT_EQ(grid.cellOfRow(p.row), cr);
        ASSERT_GT(grid.probabilityInCell(p.column, p.row), 0.0);
        ASSERT_TRUE(u.x >= 0.0 && u.x < 1.0 && u.y >= 0.0 && u.y < 1.0);
        observed[p.row * kWidth + p.column] += 1.0;
      }
      std::vector<double> seen, expected;
      for (std::size_t row = grid.rowStart(cr); row < grid.rowStart(cr + 1); ++row)
        for (std::size_t column = grid.columnStart(cc); column < grid.columnStart(cc + 1); ++column) {
          seen.push_back(observed[row * kWidth + column]);
          expected.push_back(grid.probabilityInCell(column, row) * n);
        }
      const PooledChi2 chi2 = pooledChi2(seen, expected);
      EXPECT_GT(chi2.p, 1e-4) << "cell " << cc << ", " << cr << ": χ² " << chi2.statistic << " over " << chi2.bins << " bins";
    }
}

}  // namespace glossy::test
