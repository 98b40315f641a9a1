// The correlated multi-jittered sampler: its permutations are permutations, every pixel's N samples are
// stratified as the header promises for any N (cells, thin columns and rows, 1D intervals), each sample is
// uniform (unbiased), and values are deterministic and decorrelated.
#include "renderer/samplers/cmj_sampler.h"
#include "tests/support/chi2.h"
#include "tests/support/test_support.h"

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace glossy::test {

namespace {

const std::vector<uint32_t> kCounts = {1, 2, 3, 4, 5, 6, 7, 8, 16, 17, 63, 64, 85, 86, 89, 90, 97, 100, 128, 130, 256};

std::vector<Vec2> points2D(const CmjPattern& g, uint32_t seed, uint32_t dimension) {
  CmjPixel pixel(seed, 0, 3, 4);
  std::vector<Vec2> out;
  for (uint32_t i = 0; i < g.count(); ++i) {
    CmjSampler s(g, pixel, i);
    for (uint32_t d = 0; d < dimension; ++d) s.get2D();
    out.push_back(s.get2D());
  }
  return out;
}

}  // namespace

TEST(CmjSampler, PermuteIsAPermutationOfEveryRange) {
  for (uint32_t size = 1; size <= 300; ++size)
    for (uint64_t seed : {uint64_t(0), uint64_t(1), uint64_t(0xdeadbeef12345678u), uint64_t(0x0123456789abcdefu)}) {
      std::set<uint32_t> seen;
      for (uint32_t i = 0; i < size; ++i) seen.insert(cmj_detail::permute(i, cmj_detail::PermutationRange(size), seed));
      ASSERT_EQ(seen.size(), size) << "size " << size << " seed " << seed;
      ASSERT_LT(*seen.rbegin(), size);
    }
}

TEST(CmjSampler, LayoutIsAFullGridOrColumnsOfTwoHeights) {
  struct Layout {
    uint32_t columns, rows, wide;
    bool operator==(const Layout&) const = default;
  };
  const auto layout = [](uint32_t n) { const CmjPattern g(n); return Layout{g.columns(), g.rows(), g.wideColumns()}; };
  EXPECT_EQ(layout(90), (Layout{9, 10, 0}));   // 9 × 10
  EXPECT_EQ(layout(128), (Layout{8, 16, 0}));  // 8 × 16, not 11 columns of two heights
  EXPECT_EQ(layout(64), (Layout{8, 8, 0}));
  EXPECT_EQ(layout(84), (Layout{7, 12, 0}));   // the squarest full grid with n ≤ 2m
  EXPECT_EQ(layout(89), (Layout{9, 9, 8}));    // prime: 8 columns of 10 cells and 1 of 9
  EXPECT_EQ(layout(86), (Layout{9, 9, 5}));    // 2 × 43 has no grid with n ≤ 2m
  EXPECT_EQ(layout(7), (Layout{2, 3, 1}));     // a column of 4 and one of 3
  EXPECT_EQ(layout(5), (Layout{2, 2, 1}));
  EXPECT_EQ(layout(3), (Layout{1, 3, 0}));     // below 4 only 1 × N
  EXPECT_EQ(layout(2), (Layout{1, 2, 0}));
  EXPECT_EQ(layout(0), (Layout{1, 1, 0}));     // treated as 1
}

// Exactly one point per cell, per thin column (1/N wide) and per thin row of the columns of one height.
TEST(CmjSampler, EveryDimensionPairIsMultiJitteredForAnyCount) {
  for (uint32_t n : kCounts) {
    const CmjPattern g(n);
    const uint32_t m = g.columns(), q = g.rows(), r = g.wideColumns(), wideCells = r * (q + 1);
    ASSERT_EQ(m * q + r, n);
    for (uint32_t seed : {1u, 77u})
      for (uint32_t dimension : {0u, 1u, 5u}) {
        const std::vector<Vec2> pts = points2D(g, seed, dimension);
        std::set<std::pair<uint32_t, uint32_t>> cell, thinRow;
        std::set<uint32_t> thinColumn;
        for (const Vec2& u : pts) {
          ASSERT_TRUE(u.x >= 0.0 && u.x < 1.0 && u.y >= 0.0 && u.y < 1.0);
          const uint32_t t = uint32_t(u.x * n);  // the thin column; its column and that column's height:
          const bool wide = t < wideCells;
          const uint32_t column = wide ? t / (q + 1) : r + (t - wideCells) / q, height = wide ? q + 1 : q;
          cell.insert({column, uint32_t(u.y * height)});
          thinColumn.insert(t);
          thinRow.insert({wide, uint32_t(u.y * height * (wide ? r : m - r))});
        }
        ASSERT_EQ(cell.size(), n) << "N " << n << ": two samples share a cell";
        ASSERT_EQ(thinColumn.size(), n) << "N " << n << ": two samples share a thin column";
        ASSERT_EQ(thinRow.size(), n) << "N " << n << ": two samples share a thin row";
      }
  }
}

// A vertex's split draws (several light samples per sample) from the pattern of N × splits points: the
// pixel's N samples' draws of that dimension together fill every thin column and thin row of that pattern,
// as N × splits samples would; the 1D draws every interval of N × splits. With one split they are the
// plain draws.
TEST(CmjSampler, SplitDrawsOfAPixelAreStratifiedTogether) {
  for (uint32_t n : {16u, 7u, 64u})
    for (uint32_t splits : {1u, 3u, 4u}) {
      const CmjPattern g(n, splits);
      const uint32_t total = n * splits;
      ASSERT_EQ(g.split().count(), total);
      CmjPixel pixel(9, 0, 3, 4);
      std::set<uint32_t> thinColumn, interval;
      for (uint32_t i = 0; i < n; ++i) {
        CmjSampler s(g, pixel, i), plain(g, pixel, i);
        s.skip(2);
        plain.skip(2);
        Vec2 out[8];
        double line[8];
        s.getSplits2D(splits, out);
        s.getSplits1D(splits, line);
        if (splits == 1) {
          ASSERT_EQ(out[0], plain.get2D());
          ASSERT_EQ(line[0], plain.get1D());
        }
        for (uint32_t k = 0; k < splits; ++k) {
          ASSERT_TRUE(out[k].x >= 0.0 && out[k].x < 1.0 && out[k].y >= 0.0 && out[k].y < 1.0);
          thinColumn.insert(uint32_t(out[k].x * total));
          interval.insert(uint32_t(line[k] * total));
        }
      }
      EXPECT_EQ(thinColumn.size(), total) << "N " << n << " × " << splits << ": two draws share a thin column";
      EXPECT_EQ(interval.size(), total) << "N " << n << " × " << splits << ": two 1D draws share an interval";
    }
}

TEST(CmjSampler, OneDimensionalValuesFillEveryIntervalOnce) {
  for (uint32_t n : kCounts) {
    const CmjPattern g(n);
    CmjPixel pixel(5, 0, 1, 2);
    std::set<uint32_t> strata;
    for (uint32_t i = 0; i < n; ++i) {
      CmjSampler s(g, pixel, i);
      s.get2D();
      const double v = s.get1D();
      ASSERT_TRUE(v >= 0.0 && v < 1.0);
      strata.insert(uint32_t(v * n));
    }
    ASSERT_EQ(strata.size(), n) << "N " << n;
  }
}

// Every sample is uniform on the square (and every 1D value on [0, 1)), over pixels: a χ² test of where a
// pixel's samples land on a 16 × 16 lattice (not aligned with the cells) finds no bias. Two ways to fail
// that it catches: columns of two heights that are not as wide as their share of the samples (N = 7, 85),
// and permutations whose value for a given input is not uniform over seeds (a ±15 % bias at N = 90). A pixel's
// samples are stratified, so the counts vary less than multinomially: the test is conservative.
TEST(CmjSampler, SamplesAreUniformOverPixels) {
  for (uint32_t n : {7u, 85u, 90u, 128u}) {
    const CmjPattern g(n);
    constexpr int kBins = 16;
    const int pixels = int(4000000 / n);
    std::vector<double> count2D(kBins * kBins, 0.0), count1D(kBins, 0.0);
    for (int p = 0; p < pixels; ++p) {
      CmjPixel pixel(11, 0, uint32_t(p % 1000), uint32_t(p / 1000));
      for (uint32_t i = 0; i < n; ++i) {
        CmjSampler s(g, pixel, i);
        const Vec2 u = s.get2D();
        count2D[size_t(int(u.y * kBins) * kBins + int(u.x * kBins))] += 1.0;
        count1D[size_t(s.get1D() * kBins)] += 1.0;
      }
    }
    for (const std::vector<double>* c : {&count2D, &count1D}) {
      const double expected = double(n) * pixels / double(c->size());
      double chi2 = 0.0;
      for (double k : *c) chi2 += (k - expected) * (k - expected) / expected;
      EXPECT_GT(chi2Survival(chi2, int(c->size()) - 1), 1e-3)
          << "N " << n << (c == &count2D ? " 2D" : " 1D") << ": chi2 " << chi2 << " for " << c->size() << " bins";
    }
  }
}

TEST(CmjSampler, DeterministicAndDecorrelatedAcrossPixelsPassesAndDimensions) {
  const CmjPattern g(64);
  CmjPixel pa(1, 0, 10, 20), pb(1, 0, 10, 20), pc(2, 0, 10, 20), pd(1, 0, 11, 20), pe(1, 64, 10, 20);
  CmjSampler a(g, pa, 5), b(g, pb, 5), c(g, pc, 5), d(g, pd, 5), e(g, pe, 5);
  const Vec2 ua = a.get2D(), ub = b.get2D(), uc = c.get2D(), ud = d.get2D(), ue = e.get2D();
  EXPECT_EQ(ua, ub);  // same seed, pixel, pass, index
  EXPECT_NE(ua, uc);  // another seed
  EXPECT_NE(ua, ud);  // another pixel
  EXPECT_NE(ua, ue);  // another progressive pass
  EXPECT_NE(a.get2D(), ua);  // the next dimension

  // A pixel's dimension pairs use unrelated shuffles: the correlation of dimension 0's x with dimension
  // 1's x over a pixel's 1024 samples is that of independent values.
  const CmjPattern big(1024);
  CmjPixel p(3, 0, 0, 0);
  double sxy = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0;
  for (uint32_t i = 0; i < big.count(); ++i) {
    CmjSampler s(big, p, i);
    const double x = s.get2D().x, y = s.get2D().x;
    sx += x, sy += y, sxy += x * y, sxx += x * x, syy += y * y;
  }
  const double n = big.count();
  const double r = (sxy / n - sx / n * sy / n) / std::sqrt((sxx / n - sx * sx / n / n) * (syy / n - sy * sy / n / n));
  EXPECT_LT(std::abs(r), 4.0 / std::sqrt(n)) << "correlation " << r;
}

// The batch draws the path tracer makes (CmjSampler::get2D/get1D over lanes): for every count, each lane
// gets exactly what it gets drawing alone, whatever the other lanes are (other pixels, passes, sample
// indices, dimensions), for lanes in any order and more lanes than one pass holds, and each lane's
// dimension advances as one draw would advance it.
TEST(CmjSampler, BatchDrawsEqualOneLaneDraws) {
  std::mt19937 rng(4);
  for (uint32_t n : kCounts) {
    const CmjPattern g(n);
    const int lanes = 150;
    std::vector<CmjPixel> pixels;
    for (uint32_t p = 0; p < 5; ++p) pixels.emplace_back(7 + p % 2, p / 4, p, 2 * p);
    std::vector<CmjSampler> batch, alone;
    for (int l = 0; l < lanes; ++l) {
      const uint32_t index = uint32_t(rng() % n), advance = rng() % 4;
      batch.emplace_back(g, pixels[size_t(l) % pixels.size()], index);
      alone.emplace_back(g, pixels[size_t(l) % pixels.size()], index);
      for (uint32_t d = 0; d < advance; ++d) {
        batch.back().get1D();
        alone.back().get1D();
      }
    }
    // Every other lane, backwards from the end, then all of them in order: a lane in two lists draws twice.
    std::vector<int> some, all(lanes);
    for (int l = lanes - 1; l >= 0; l -= 2) some.push_back(l);
    for (int l = 0; l < lanes; ++l) all[size_t(l)] = l;
    std::vector<Vec2> u2(lanes, Vec2(-1.0));
    std::vector<double> u1(lanes, -1.0);
    for (int round = 0; round < 3; ++round) {
      const std::vector<int>& list = round == 1 ? some : all;
      CmjSampler::get2D(batch.data(), list.data(), int(list.size()), u2.data());
      CmjSampler::get1D(batch.data(), list.data(), int(list.size()), u1.data());
      for (int l : list) {
        ASSERT_EQ(u2[size_t(l)], alone[size_t(l)].get2D()) << "N " << n << " lane " << l << " round " << round;
        ASSERT_EQ(u1[size_t(l)], alone[size_t(l)].get1D()) << "N " << n << " lane " << l << " round " << round;
      }
    }
    for (int l = 0; l < lanes; ++l) ASSERT_EQ(batch[size_t(l)].get2D(), alone[size_t(l)].get2D()) << "dimension of lane " << l;
  }
}

// The split forms likewise: each lane's split draws (several light or BSDF samples of one vertex) come out
// of the batch as getSplits2D / getSplits1D give them alone, lanes with different counts in one batch, more
// draws than one pass holds, each lane's dimension advanced by one.
TEST(CmjSampler, BatchSplitDrawsEqualOneLaneSplitDraws) {
  std::mt19937 rng(5);
  const uint32_t countsOf[] = {8, 1, 4, 24, 3, 2};
  for (uint32_t n : {16u, 7u, 64u}) {
    const CmjPattern g(n, 24);
    const int lanes = 140;
    std::vector<CmjPixel> pixels;
    for (uint32_t p = 0; p < 5; ++p) pixels.emplace_back(3 + p % 2, p / 4, p, 3 * p);
    std::vector<CmjSampler> batch, alone;
    std::vector<uint32_t> counts(lanes);
    for (int l = 0; l < lanes; ++l) {
      const uint32_t index = uint32_t(rng() % n);
      batch.emplace_back(g, pixels[size_t(l) % pixels.size()], index);
      alone.emplace_back(g, pixels[size_t(l) % pixels.size()], index);
      counts[size_t(l)] = countsOf[rng() % std::size(countsOf)];
    }
    std::vector<int> all(lanes);
    for (int l = 0; l < lanes; ++l) all[size_t(l)] = l;
    constexpr int kMost = 24;
    std::vector<std::array<Vec2, kMost>> u2(lanes);
    std::vector<std::array<double, kMost>> u1(lanes);
    std::vector<Vec2*> to2(lanes);
    std::vector<double*> to1(lanes);
    for (int l = 0; l < lanes; ++l) to2[size_t(l)] = u2[size_t(l)].data(), to1[size_t(l)] = u1[size_t(l)].data();
    CmjSampler::getSplits2D(batch.data(), all.data(), lanes, counts.data(), to2.data());
    CmjSampler::getSplits1D(batch.data(), all.data(), lanes, counts.data(), to1.data());
    for (int l = 0; l < lanes; ++l) {
      std::array<Vec2, kMost> want2;
      std::array<double, kMost> want1;
      alone[size_t(l)].getSplits2D(counts[size_t(l)], want2.data());
      alone[size_t(l)].getSplits1D(counts[size_t(l)], want1.data());
      for (uint32_t d = 0; d < counts[size_t(l)]; ++d) {
        ASSERT_EQ(u2[size_t(l)][size_t(d)], want2[size_t(d)]) << "N " << n << " lane " << l << " draw " << d;
        ASSERT_EQ(u1[size_t(l)][size_t(d)], want1[size_t(d)]) << "N " << n << " lane " << l << " draw " << d;
      }
      ASSERT_EQ(batch[size_t(l)].get2D(), alone[size_t(l)].get2D()) << "dimension of lane " << l;
    }
  }
}

}  // namespace glossy::test
