// The statistical tools the study's analysis is built from, each a textbook procedure on plain vectors so
// that it can be checked against an independent implementation (tests/study_statistics_test.cpp holds
// scipy's figures). Distributions come from Boost.Math. A statistic that is undefined for its data
// (a constant column, too few pairs) is nullopt with a reason, never NaN.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace glossy::study {

// The mean and the median of `v`; nullopt when it is empty.
std::optional<double> meanOf(const std::vector<double>& v);
std::optional<double> medianOf(std::vector<double> v);

// Ranks 1…n of `v`, ties given the mean of the ranks they span (scipy.stats.rankdata, method "average").
std::vector<double> averageRanks(const std::vector<double>& v);
// Σ (t³ − t) over the groups of t equal values: the tie term of rank statistics.
double tieTerm(const std::vector<double>& v);

// Spearman's ρ (Pearson's r of the average ranks) and Kendall's τ-b; nullopt when either column is
// constant or n < 2 (the correlation is undefined there).
std::optional<double> spearman(const std::vector<double>& x, const std::vector<double>& y);
std::optional<double> kendallTauB(const std::vector<double>& x, const std::vector<double>& y);

// Kendall's coefficient of concordance W of m raters (rows) ranking the same n items (columns), with the
// tie correction: W = 12 S / (m² (n³ − n) − m Σ T). nullopt for m < 2, n < 2, or when every rater ties
// every item.
std::optional<double> kendallW(const std::vector<std::vector<double>>& scores);

struct FriedmanResult {
  int blocks = 0, treatments = 0;
  double chiSquare = 0, pChiSquare = 1;           // tie-corrected, as scipy.stats.friedmanchisquare
  // F = (N−1)χ² / (N(k−1) − χ²) on (k−1, (k−1)(N−1)) df; absent (infinite, pF = 0) when every block ranks
  // the treatments alike.
  std::optional<double> imanDavenportF, pF;
  std::vector<double> meanRanks;                   // per treatment, 1 = lowest value
};
// Friedman's test over blocks (rows, e.g. materials) × treatments (columns, models), lower value = rank 1.
// nullopt for fewer than 2 blocks or 2 treatments, or when every block ties every treatment.
std::optional<FriedmanResult> friedman(const std::vector<std::vector<double>>& blocks);

struct WilcoxonResult {
  int n = 0;          // pairs with a non-zero difference (zeros are dropped: Wilcoxon's zero method)
  int zeros = 0;      // pairs dropped for a zero difference
  double statistic = 0;  // min(W+, W−)
  double p = 1;          // two-sided
  std::string method;    // "exact" or "normal approximation (tie-corrected, no continuity correction)"
};
// Minimum non-zero differences for a test: below 6, no two-sided exact p can reach 0.05.
constexpr int kWilcoxonMinPairs = 6;
// Exact null distribution up to this many pairs when no |difference| ties; the normal approximation beyond.
constexpr int kWilcoxonExactMax = 25;
// Wilcoxon's signed-rank test of x − y; nullopt (with `reason` set) when fewer than kWilcoxonMinPairs
// differences are non-zero.
std::optional<WilcoxonResult> wilcoxonSignedRank(const std::vector<double>& x, const std::vector<double>& y,
                                                 std::string* reason = nullptr);

// Holm's step-down adjustment of p values (same order as given).
std::vector<double> holm(const std::vector<double>& p);

// The survival functions used above, from Boost.Math.
double chiSquareSf(double x, double df);
double fSf(double x, double df1, double df2);
double normalSf(double z);

// Percentile of sorted values, linear between order statistics (numpy's default, "type 7").
double quantileSorted(const std::vector<double>& sorted, double q);

// A seeded resampler whose draws are the same on every platform (std::mt19937_64 is; the standard's
// distributions are not, so the index is drawn by rejection here).
class Resampler {
 public:
  explicit Resampler(std::uint64_t seed) : rng_(seed) {}
  std::size_t index(std::size_t n);
  std::vector<std::size_t> draw(std::size_t n);  // n indices in [0, n) with replacement

 private:
  std::mt19937_64 rng_;
};

struct Interval {
  std::optional<double> estimate, lo, hi;
  int resamples = 0, undefined = 0;  // resamples whose statistic was undefined (left out of the interval)
  std::string reason;                // why the estimate or interval is absent
};
// The statistic on `units` and its 95 % percentile bootstrap interval: `resamples` draws of the units (the
// sampling unit, e.g. materials) with replacement, seeded. The interval is absent when fewer than half of
// the resamples give a defined statistic.
Interval bootstrap(std::size_t units, const std::function<std::optional<double>(const std::vector<std::size_t>&)>& statistic,
                   int resamples, std::uint64_t seed);

}  // namespace glossy::study
