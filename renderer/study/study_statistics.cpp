#include "renderer/study/study_statistics.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace glossy::study {

std::optional<double> meanOf(const std::vector<double>& v) {
  if (v.empty()) return std::nullopt;
  return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

std::optional<double> medianOf(std::vector<double> v) {
  if (v.empty()) return std::nullopt;
  std::sort(v.begin(), v.end());
  return quantileSorted(v, 0.5);
}

std::vector<double> averageRanks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> ranks(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    const double rank = 0.5 * double(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = rank;
    i = j + 1;
  }
  return ranks;
}

double tieTerm(const std::vector<double>& v) {
  std::vector<double> s = v;
  std::sort(s.begin(), s.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < s.size();) {
    std::size_t j = i;
    while (j < s.size() && s[j] == s[i]) ++j;
    const double t = double(j - i);
    sum += t * t * t - t;
    i = j;
  }
  return sum;
}

namespace {

std::optional<double> pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 2 || y.size() != n) return std::nullopt;
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / double(n);
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / double(n);
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx <= 0.0 || syy <= 0.0) return std::nullopt;
  return std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
}

}  // namespace

std::optional<double> spearman(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 2) return std::nullopt;
  return pearson(averageRanks(x), averageRanks(y));
}

namespace {

// Pairs i < j with v[i] > v[j], by merge sort: O(n log n).
std::int64_t inversions(std::vector<double>& v, std::vector<double>& buffer, std::size_t lo, std::size_t hi) {
  if (hi - lo < 2) return 0;
  const std::size_t mid = lo + (hi - lo) / 2;
  std::int64_t count = inversions(v, buffer, lo, mid) + inversions(v, buffer, mid, hi);
  std::size_t i = lo, j = mid, k = lo;
  while (i < mid && j < hi) {
    if (v[j] < v[i]) {
      count += std::int64_t(mid - i);
      buffer[k++] = v[j++];
    } else {
      buffer[k++] = v[i++];
    }
  }
  while (i < mid) buffer[k++] = v[i++];
  while (j < hi) buffer[k++] = v[j++];
  std::copy(buffer.begin() + std::ptrdiff_t(lo), buffer.begin() + std::ptrdiff_t(hi), v.begin() + std::ptrdiff_t(lo));
  return count;
}

// Σ t(t − 1)/2 over runs of equal values in `sorted`.
template <class Eq>
std::int64_t tiedPairs(std::size_t n, Eq equal) {
  std::int64_t sum = 0;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    while (j < n && equal(i, j)) ++j;
    const std::int64_t t = std::int64_t(j - i);
    sum += t * (t - 1) / 2;
    i = j;
  }
  return sum;
}

}  // namespace

std::optional<double> kendallTauB(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 2 || y.size() != n) return std::nullopt;
  // Knight's O(n log n) count (as scipy.stats.kendalltau): the bootstraps recompute it thousands of times.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return std::tie(x[a], y[a]) < std::tie(x[b], y[b]); });
  const std::int64_t total = std::int64_t(n) * std::int64_t(n - 1) / 2;
  const std::int64_t tiesX = tiedPairs(n, [&](std::size_t i, std::size_t j) { return x[order[i]] == x[order[j]]; });
  const std::int64_t tiesXY =
      tiedPairs(n, [&](std::size_t i, std::size_t j) { return x[order[i]] == x[order[j]] && y[order[i]] == y[order[j]]; });
  std::vector<double> ys(n), buffer(n);
  for (std::size_t i = 0; i < n; ++i) ys[i] = y[order[i]];
  // Within a run of equal x the y are ascending, so every inversion is a discordant pair.
  const std::int64_t discordant = inversions(ys, buffer, 0, n);
  const std::int64_t tiesY = tiedPairs(n, [&](std::size_t i, std::size_t j) { return ys[i] == ys[j]; });  // ys now sorted
  const double concordantMinusDiscordant = double(total - tiesX - tiesY + tiesXY - 2 * discordant);
  const double denom = std::sqrt(double(total - tiesX) * double(total - tiesY));
  if (!(denom > 0.0)) return std::nullopt;
  return std::clamp(concordantMinusDiscordant / denom, -1.0, 1.0);
}

namespace {

// What Kendall's W and Friedman's test both start from: each column's sum of its within-row average ranks,
// and the rows' tie terms summed; nullopt unless there are 2 rows or more of the same 2 values or more.
struct RankSums {
  std::vector<double> sums;
  double ties = 0.0;
};

std::optional<RankSums> rankSums(const std::vector<std::vector<double>>& rows) {
  if (rows.size() < 2 || rows[0].size() < 2) return std::nullopt;
  RankSums out{std::vector<double>(rows[0].size(), 0.0)};
  for (const auto& row : rows) {
    if (row.size() != out.sums.size()) return std::nullopt;
    const auto r = averageRanks(row);
    for (std::size_t j = 0; j < r.size(); ++j) out.sums[j] += r[j];
    out.ties += tieTerm(row);
  }
  return out;
}

}  // namespace

std::optional<double> kendallW(const std::vector<std::vector<double>>& scores) {
  const auto ranks = rankSums(scores);
  if (!ranks) return std::nullopt;
  const std::size_t m = scores.size(), n = ranks->sums.size();
  const double mean = double(m) * double(n + 1) / 2.0;
  double s = 0.0;
  for (double r : ranks->sums) s += (r - mean) * (r - mean);
  const double dm = double(m), dn = double(n);
  const double denom = dm * dm * (dn * dn * dn - dn) - dm * ranks->ties;
  if (!(denom > 0.0)) return std::nullopt;
  return std::clamp(12.0 * s / denom, 0.0, 1.0);
}

std::optional<FriedmanResult> friedman(const std::vector<std::vector<double>>& blocks) {
  const auto ranks = rankSums(blocks);
  if (!ranks) return std::nullopt;
  const std::size_t nb = blocks.size(), k = ranks->sums.size();
  const double n = double(nb), dk = double(k);
  const double c = 1.0 - ranks->ties / (n * (dk * dk * dk - dk));
  if (!(c > 0.0)) return std::nullopt;
  double ss = 0.0;
  for (double r : ranks->sums) ss += r * r;
  FriedmanResult out;
  out.blocks = int(nb);
  out.treatments = int(k);
  out.chiSquare = std::max(0.0, (12.0 / (n * dk * (dk + 1.0)) * ss - 3.0 * n * (dk + 1.0)) / c);
  out.pChiSquare = chiSquareSf(out.chiSquare, dk - 1.0);
  const double fDenom = n * (dk - 1.0) - out.chiSquare;
  if (fDenom > 0.0) {
    out.imanDavenportF = (n - 1.0) * out.chiSquare / fDenom;
    out.pF = fSf(*out.imanDavenportF, dk - 1.0, (dk - 1.0) * (n - 1.0));
  } else {
    out.pF = 0.0;  // every block ranks the treatments alike: F is infinite
  }
  for (double r : ranks->sums) out.meanRanks.push_back(r / n);
  return out;
}

std::optional<WilcoxonResult> wilcoxonSignedRank(const std::vector<double>& x, const std::vector<double>& y,
                                                 std::string* reason) {
  WilcoxonResult out;
  std::vector<double> d;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    const double diff = x[i] - y[i];
    if (diff == 0.0) {
      ++out.zeros;
    } else {
      d.push_back(diff);
    }
  }
  out.n = int(d.size());
  if (out.n < kWilcoxonMinPairs) {
    if (reason)
      *reason = std::to_string(out.n) + " non-zero differences (" + std::to_string(out.zeros) +
                " zero): fewer than " + std::to_string(kWilcoxonMinPairs) + ", no two-sided p can fall below 0.05";
    return std::nullopt;
  }
  std::vector<double> absd(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) absd[i] = std::fabs(d[i]);
  const auto r = averageRanks(absd);
  double wPlus = 0.0, wMinus = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) (d[i] > 0.0 ? wPlus : wMinus) += r[i];
  out.statistic = std::min(wPlus, wMinus);
  const double ties = tieTerm(absd);
  const int n = out.n;
  if (n <= kWilcoxonExactMax && ties == 0.0) {
    // The null distribution of W+: each rank's sign is a fair coin, so count the subsets of {1…n} by sum.
    const int maxSum = n * (n + 1) / 2;
    std::vector<double> count(std::size_t(maxSum) + 1, 0.0);
    count[0] = 1.0;
    for (int rank = 1; rank <= n; ++rank)
      for (int s = maxSum; s >= rank; --s) count[std::size_t(s)] += count[std::size_t(s - rank)];
    double below = 0.0;
    for (int s = 0; s <= int(std::floor(out.statistic + 1e-9)); ++s) below += count[std::size_t(s)];
    out.p = std::min(1.0, 2.0 * below / std::ldexp(1.0, n));
    out.method = "exact";
  } else {
    const double dn = double(n);
    const double mean = dn * (dn + 1.0) / 4.0;
    const double var = dn * (dn + 1.0) * (2.0 * dn + 1.0) / 24.0 - ties / 48.0;
    const double z = var > 0.0 ? (out.statistic - mean) / std::sqrt(var) : 0.0;
    out.p = std::min(1.0, 2.0 * normalSf(std::fabs(z)));
    out.method = "normal approximation (tie-corrected, no continuity correction)";
  }
  return out;
}

std::vector<double> holm(const std::vector<double>& p) {
  const std::size_t m = p.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<double> adjusted(m);
  double running = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    running = std::max(running, std::min(1.0, double(m - i) * p[order[i]]));
    adjusted[order[i]] = running;
  }
  return adjusted;
}

double chiSquareSf(double x, double df) {
  if (!(x > 0.0)) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared_distribution<double>(df), x));
}

double fSf(double x, double df1, double df2) {
  if (!(x > 0.0)) return 1.0;
  if (std::isinf(x)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(df1, df2), x));
}

double normalSf(double z) {
  return boost::math::cdf(boost::math::complement(boost::math::normal_distribution<double>(0.0, 1.0), z));
}

double quantileSorted(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double pos = q * double(sorted.size() - 1);
  const std::size_t i = std::size_t(std::floor(pos));
  if (i + 1 >= sorted.size()) return sorted.back();
  return sorted[i] + (pos - double(i)) * (sorted[i + 1] - sorted[i]);
}

std::size_t Resampler::index(std::size_t n) {
  const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t rem = (max % n + 1) % n;  // 2^64 mod n: draws at or above 2^64 − rem would bias
  for (;;) {
    const std::uint64_t x = rng_();
    if (rem == 0 || x <= max - rem) return std::size_t(x % n);
  }
}

std::vector<std::size_t> Resampler::draw(std::size_t n) {
  std::vector<std::size_t> out(n);
  for (auto& i : out) i = index(n);
  return out;
}

Interval bootstrap(std::size_t units, const std::function<std::optional<double>(const std::vector<std::size_t>&)>& statistic,
                   int resamples, std::uint64_t seed) {
  Interval out;
  std::vector<std::size_t> all(units);
  std::iota(all.begin(), all.end(), 0);
  out.estimate = units > 0 ? statistic(all) : std::nullopt;
  if (!out.estimate) {
    out.reason = units == 0 ? "no data" : "undefined on these data";
    return out;
  }
  Resampler resampler(seed);
  std::vector<double> values;
  values.reserve(std::size_t(std::max(resamples, 0)));
  for (int r = 0; r < resamples; ++r) {
    if (const auto v = statistic(resampler.draw(units))) {
      values.push_back(*v);
    } else {
      ++out.undefined;
    }
  }
  out.resamples = resamples;
  if (resamples <= 0 || 2 * out.undefined > resamples) {
    out.reason = "undefined in " + std::to_string(out.undefined) + " of " + std::to_string(resamples) + " resamples";
    return out;
  }
  std::sort(values.begin(), values.end());
  out.lo = quantileSorted(values, 0.025);
  out.hi = quantileSorted(values, 0.975);
  return out;
}

}  // namespace glossy::study
