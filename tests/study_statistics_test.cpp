// The study's statistical tools (renderer/study/study_statistics.h) against scipy 1.17.1, computed in a
// throwaway virtual environment outside the repository; each figure carries the call that produced it.
#include "renderer/study/study_statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glossy::study {
namespace {

const std::vector<double> kX = {1, 2, 3, 4, 5, 6, 7, 8}, kY = {2, 1, 4, 3, 7, 8, 6, 5};
const std::vector<double> kXt = {1, 2, 2, 3, 4, 5, 5, 6}, kYt = {1, 3, 2, 2, 5, 4, 4, 7};

TEST(StudyStatistics, AverageRanksShareTies) {
  // scipy.stats.rankdata([3, 1, 4, 1, 5]) → [3, 1.5, 4, 1.5, 5]
  EXPECT_EQ(averageRanks({3, 1, 4, 1, 5}), (std::vector<double>{3, 1.5, 4, 1.5, 5}));
  EXPECT_EQ(tieTerm({1, 1, 2, 3, 3, 3}), 6.0 + 24.0);
}

TEST(StudyStatistics, SpearmanMatchesScipy) {
  // scipy.stats.spearmanr(kX, kY).statistic
  EXPECT_NEAR(*spearman(kX, kY), 0.7380952380952381, 1e-12);
  // scipy.stats.spearmanr(kXt, kYt).statistic (ties in both columns)
  EXPECT_NEAR(*spearman(kXt, kYt), 0.8719512195121952, 1e-12);
}

TEST(StudyStatistics, KendallTauBMatchesScipy) {
  // scipy.stats.kendalltau(kX, kY).statistic (variant "b", the default)
  EXPECT_NEAR(*kendallTauB(kX, kY), 0.5, 1e-12);
  // scipy.stats.kendalltau(kXt, kYt).statistic
  EXPECT_NEAR(*kendallTauB(kXt, kYt), 0.7307692307692308, 1e-12);
}

// Kendall's τ-b by its definition, pair by pair: the O(n log n) count must agree with it.
double bruteTauB(const std::vector<double>& x, const std::vector<double>& y) {
  double c = 0, d = 0, tx = 0, ty = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      const double dx = x[i] - x[j], dy = y[i] - y[j];
      if (dx == 0 && dy == 0) continue;
      if (dx == 0) {
        tx += 1;
      } else if (dy == 0) {
        ty += 1;
      } else {
        (dx * dy > 0 ? c : d) += 1;
      }
    }
  return (c - d) / std::sqrt((c + d + tx) * (c + d + ty));
}

TEST(StudyStatistics, KendallTauBAgreesWithThePairByPairCount) {
  Resampler r(3);
  for (int trial = 0; trial < 50; ++trial) {
    const std::size_t n = 2 + r.index(60);
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = double(r.index(8));  // few distinct values: ties in x, in y and in both
      y[i] = double(r.index(trial % 2 ? 5 : 1000));
    }
    const auto tau = kendallTauB(x, y);
    if (!tau) continue;
    EXPECT_NEAR(*tau, bruteTauB(x, y), 1e-12) << "n " << n;
  }
}

TEST(StudyStatistics, ConstantColumnsHaveNoCorrelation) {
  const std::vector<double> constant(8, 0.3);
  EXPECT_FALSE(spearman(kX, constant));
  EXPECT_FALSE(kendallTauB(constant, kY));
  EXPECT_FALSE(spearman({1.0}, {2.0}));
}

TEST(StudyStatistics, FriedmanAndImanDavenportMatchScipy) {
  const std::vector<std::vector<double>> blocks = {{0.10, 0.20, 0.20, 0.40}, {0.30, 0.10, 0.25, 0.50}, {0.12, 0.15, 0.11, 0.40},
                                                   {0.22, 0.22, 0.22, 0.30}, {0.05, 0.30, 0.20, 0.35}, {0.15, 0.10, 0.30, 0.60}};
  const auto f = friedman(blocks);
  ASSERT_TRUE(f);
  // r = scipy.stats.friedmanchisquare(*B.T): statistic, pvalue (tie-corrected)
  EXPECT_NEAR(f->chiSquare, 11.945454545454549, 1e-10);
  EXPECT_NEAR(f->pChiSquare, 0.0075723650654218174, 1e-12);
  // F = (N-1) chi / (N (k-1) - chi); scipy.stats.f.sf(F, k-1, (k-1)(N-1))
  ASSERT_TRUE(f->imanDavenportF && f->pF);
  EXPECT_NEAR(*f->imanDavenportF, 9.864864864864874, 1e-9);
  EXPECT_NEAR(*f->pF, 0.0007678207911409922, 1e-12);
  // scipy.stats.rankdata(B, axis=1).mean(axis=0)
  EXPECT_NEAR(f->meanRanks[0], 1.8333333333333333, 1e-12);
  EXPECT_NEAR(f->meanRanks[1], 2.0833333333333333, 1e-12);
  EXPECT_NEAR(f->meanRanks[3], 4.0, 1e-12);
}

TEST(StudyStatistics, FriedmanNeedsTwoBlocksAndSomeOrder) {
  EXPECT_FALSE(friedman({{0.1, 0.2, 0.3}}));
  EXPECT_FALSE(friedman({{0.1, 0.1, 0.1}, {0.2, 0.2, 0.2}}));  // every block ties: no ranking to test
  // Every block ranks alike: χ² = N(k−1) (scipy.stats.friedmanchisquare([1, 1, 1], [2, 2, 2], [3, 3, 3]) = 6.0),
  // the Iman–Davenport F infinite — absent, its p 0, never NaN or Inf.
  const auto same = friedman({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}});
  ASSERT_TRUE(same);
  EXPECT_NEAR(same->chiSquare, 6.0, 1e-12);
  EXPECT_FALSE(same->imanDavenportF);
  EXPECT_EQ(same->pF, 0.0);
}

TEST(StudyStatistics, KendallWWithTiesMatchesFriedman) {
  // W = chi² / (m (n − 1)) with chi² = scipy.stats.friedmanchisquare(*R.T).statistic (tie-corrected)
  const std::vector<std::vector<double>> raters = {{1, 2, 3, 4, 5}, {2, 1, 3, 5, 4}, {1, 3, 2, 4, 4}};
  EXPECT_NEAR(*kendallW(raters), 0.853107344632768, 1e-12);
  EXPECT_NEAR(*kendallW({{1, 2, 3}, {1, 2, 3}}), 1.0, 1e-12);
  EXPECT_FALSE(kendallW({{1, 2, 3}}));
  EXPECT_FALSE(kendallW({{1, 1, 1}, {2, 2, 2}}));
}

TEST(StudyStatistics, WilcoxonExactMatchesScipy) {
  // Integers: the differences (2, 3, 4, 6, 11, 13, 15, 19, 21, 24 in size) are exact, so none ties.
  const std::vector<double> a = {61, 52, 93, 44, 75, 36, 87, 28, 59, 71};
  const std::vector<double> b = {50, 56, 80, 46, 60, 30, 68, 31, 35, 50};
  const auto w = wilcoxonSignedRank(a, b);
  ASSERT_TRUE(w);
  // scipy.stats.wilcoxon(a, b, method='exact'): statistic 6.0, pvalue 0.02734375 (method='auto' agrees)
  EXPECT_EQ(w->method, "exact");
  EXPECT_EQ(w->statistic, 6.0);
  EXPECT_NEAR(w->p, 0.02734375, 1e-15);
}

TEST(StudyStatistics, WilcoxonNormalApproximationWithTiesAndZerosMatchesScipy) {
  const std::vector<double> c = {0.91, -0.01, 0.58, 0.39, 0.41, 0.46, 0.1, 0.45, 0.33, 1.16, 0.55, 0.43, 0.44, 0.37, 0.29,
                                 0.42, 0.6, 0.45, 0.69, 0.46, 0.5, 0.81, 0.61, 0.4, 0.46, 0.61, 0.89, 0.45, 0.45, 0.7};
  const std::vector<double> d = {0.91, -0.01, 0.58, 0.49, 0.51, 0.56, -0.1, 0.65, 0.33, 0.96, 0.55, 0.63, 0.44, 0.27, 0.29,
                                 0.52, 0.8, 0.65, 0.79, 0.56, 0.5, 0.81, 0.71, 0.5, 0.46, 0.61, 0.99, 0.35, 0.65, 0.8};
  const auto w = wilcoxonSignedRank(c, d);
  ASSERT_TRUE(w);
  // scipy.stats.wilcoxon(c, d, method='approx', correction=False, zero_method='wilcox'): 40.0, 0.025939715410658946
  // (11 zero differences dropped, ties among the other 19)
  EXPECT_EQ(w->zeros, 11);
  EXPECT_EQ(w->n, 19);
  EXPECT_EQ(w->statistic, 40.0);
  EXPECT_NEAR(w->p, 0.025939715410658946, 1e-12);
  EXPECT_NE(w->method.find("normal"), std::string::npos);
}

TEST(StudyStatistics, WilcoxonWithTooFewPairsIsNoTest) {
  std::string reason;
  // Five non-zero differences (and two zeros): even the most extreme sign pattern has p = 1/16 > 0.05.
  EXPECT_FALSE(wilcoxonSignedRank({1, 2, 3, 4, 5, 6, 7}, {0, 1, 2, 3, 4, 6, 7}, &reason));
  EXPECT_NE(reason.find("5 non-zero"), std::string::npos) << reason;
  EXPECT_FALSE(wilcoxonSignedRank({1, 1, 1, 1, 1, 1, 1}, {1, 1, 1, 1, 1, 1, 1}));
}

TEST(StudyStatistics, HolmAdjustsStepDown) {
  // By hand: sorted 0.005·4 = 0.02, 0.01·3 = 0.03, 0.03·2 = 0.06, 0.04·1 = 0.04 → running max 0.06.
  const auto adj = holm({0.01, 0.04, 0.03, 0.005});
  ASSERT_EQ(adj.size(), 4u);
  EXPECT_NEAR(adj[0], 0.03, 1e-15);
  EXPECT_NEAR(adj[1], 0.06, 1e-15);
  EXPECT_NEAR(adj[2], 0.06, 1e-15);
  EXPECT_NEAR(adj[3], 0.02, 1e-15);
  EXPECT_EQ(holm({0.5, 0.9})[1], 1.0);
}

TEST(StudyStatistics, DistributionsMatchScipy) {
  EXPECT_NEAR(chiSquareSf(7.5, 3), 0.0575584519726364, 1e-14);  // scipy.stats.chi2.sf(7.5, 3)
  EXPECT_NEAR(fSf(2.5, 3, 15), 0.0990819240353751, 1e-14);      // scipy.stats.f.sf(2.5, 3, 15)
  EXPECT_NEAR(normalSf(1.7), 0.04456546275854304, 1e-15);       // scipy.stats.norm.sf(1.7)
}

TEST(StudyStatistics, PercentilesInterpolateAsNumpy) {
  // numpy.percentile([1, 2, 4, 8, 16], 2.5) = 1.1, numpy.percentile(..., 97.5) = 15.2
  EXPECT_NEAR(quantileSorted({1, 2, 4, 8, 16}, 0.025), 1.1, 1e-12);
  EXPECT_NEAR(quantileSorted({1, 2, 4, 8, 16}, 0.975), 15.2, 1e-12);
}

TEST(StudyStatistics, BootstrapIsSeededAndCoversTheEstimate) {
  const std::vector<double> v = {0.1, 0.4, 0.35, 0.8, 0.2, 0.5, 0.45, 0.3, 0.6, 0.25};
  const auto mean = [&](const std::vector<std::size_t>& idx) -> std::optional<double> {
    double s = 0;
    for (auto i : idx) s += v[i];
    return s / double(idx.size());
  };
  const auto a = bootstrap(v.size(), mean, 2000, 7), b = bootstrap(v.size(), mean, 2000, 7), c = bootstrap(v.size(), mean, 2000, 8);
  ASSERT_TRUE(a.lo && a.hi);
  EXPECT_EQ(*a.lo, *b.lo);
  EXPECT_EQ(*a.hi, *b.hi);
  EXPECT_NE(*a.lo, *c.lo);
  EXPECT_NEAR(*a.estimate, 0.395, 1e-12);
  EXPECT_LT(*a.lo, *a.estimate);
  EXPECT_GT(*a.hi, *a.estimate);
  // The mean's standard error is s/√n ≈ 0.066: a 95 % interval about ±1.96 of it, within sampling error.
  EXPECT_NEAR(*a.hi - *a.lo, 2 * 1.96 * 0.0657, 0.05);
}

TEST(StudyStatistics, BootstrapOfAnUndefinedStatisticSaysWhy) {
  const auto iv = bootstrap(5, [](const std::vector<std::size_t>&) -> std::optional<double> { return std::nullopt; }, 100, 1);
  EXPECT_FALSE(iv.estimate);
  EXPECT_FALSE(iv.reason.empty());
}

TEST(StudyStatistics, ResamplerDrawsEveryIndexAndIsReproducible) {
  Resampler r(42), s(42);
  std::vector<int> seen(7, 0);
  for (int i = 0; i < 700; ++i) {
    const auto k = r.index(7);
    ASSERT_EQ(k, s.index(7));
    ASSERT_LT(k, 7u);
    ++seen[k];
  }
  for (int n : seen) EXPECT_GT(n, 50);
}

}  // namespace
}  // namespace glossy::study
