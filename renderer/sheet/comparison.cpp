#include "renderer/sheet/comparison.h"

#include "materials/core/types.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace glossy {

namespace {

using Rgb3 = std::array<double, 3>;

double dot(const Rgb3& a, const Rgb3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// z with P(|Z| ≤ z) = confidence for a standard normal Z: erfc(z / √2) = 1 − confidence, by bisection
// (erfc is decreasing; 200 halvings reach double precision).
double twoSidedQuantile(double confidence) {
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (std::erfc(mid / std::numbers::sqrt2) > 1.0 - confidence)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// The same for Student's t with ν (real, ≥ 1) degrees of freedom: P(|T| ≤ t) from its density integrated by
// Simpson's rule from 0, then bisection. Beyond 1000 degrees of freedom the normal's.
double studentQuantile(double confidence, double nu) {
  const double z = twoSidedQuantile(confidence);
  if (!(nu < 1000.0)) return z;
  const double logNorm = std::lgamma(0.5 * (nu + 1.0)) - std::lgamma(0.5 * nu) - 0.5 * std::log(nu * std::numbers::pi);
  const auto density = [&](double t) { return std::exp(logNorm - 0.5 * (nu + 1.0) * std::log1p(t * t / nu)); };
  const auto central = [&](double t) {  // P(|T| ≤ t)
    constexpr int n = 2000;
    const double h = t / n;
    double sum = density(0.0) + density(t);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * density(i * h);
    return 2.0 * sum * h / 3.0;
  };
  double lo = z, hi = 1000.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (central(mid) < confidence ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Sums over the compared pixels of per-pixel statistics. Series 0 is the measured panel, series 1 + f the
// f-th panel that has images: its difference from the measured panel in the U-statistics, the panel itself
// in the luminance sums.
struct Totals {
  size_t series;
  std::vector<double> u;         // Σ U: B, then each A
  std::vector<double> ratioVar;  // Σ Var((U_s − R_s U_0) / B) per pixel, clamped at 0 (K ≥ 4, second pass)
  std::vector<double> jack, jackSquared;  // Σ v, Σ v² of the same per-pixel variances by the jackknife (v ≥ 0)
  std::vector<double> diffVar;   // Σ Var(U_s − U_t) per pixel, clamped at 0, series × series (likewise)
  std::vector<double> squared;   // Σ |m̄|², then each Σ |p̄ − m̄|²
  std::vector<double> lum;       // Σ lum(m̄), then each Σ lum(p̄)
  std::vector<double> lumVar;    // Σ Var lum(·̄), in the same order
  std::vector<double> lumCov;    // Σ Cov(lum(·̄), lum(m̄)), in the same order
  // For the test-inversion interval (scoreInterval), second pass, with x̄ a pixel's mean and S its sample
  // covariance: Σ x̄ᵀ S x̄ of the measured panel, then each difference's; Σ d̄ᵀ S_dm m̄ per difference;
  // Σ tr(C Cᵀ) (unbiased, C the covariance of the pair) of m with m, then each d with d, and of each d with m.
  std::vector<double> projVar, projCov, trace, traceCross;
  std::vector<double> lumRatioVar, lumRatioVarSquared;  // Σ v, Σ v² of each pixel's Var of lum(p̄) − L lum(m̄)
  explicit Totals(size_t s)
      : series(s), u(s), ratioVar(s), jack(s), jackSquared(s), diffVar(s * s), squared(s), lum(s), lumVar(s), lumCov(s),
        projVar(s), projCov(s), trace(s), traceCross(s), lumRatioVar(s), lumRatioVarSquared(s) {}
  double diff(size_t s, size_t t) const { return diffVar[s * series + t]; }
};

// One pixel: x(s, j) is series s in replicate j (measured value or difference), l(s, j) the luminance of
// the panel's value.
class PixelReplicates {
 public:
  PixelReplicates(size_t series, int replicates)
      : series_(series), k_(replicates), x_(series * replicates), l_(series * replicates),
        gram_(series * replicates * replicates), rowSum_(series * replicates), total_(series), u_(series), mean_(series),
        trace_(series), cross_(series) {}
  Rgb3& x(size_t s, int j) { return x_[s * k_ + j]; }
  double& l(size_t s, int j) { return l_[s * k_ + j]; }
  bool finite() const {
    return std::all_of(x_.begin(), x_.end(), [](const Rgb3& v) {
      return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
    });
  }

  // First pass: the means and the U-statistics.
  void addTo(Totals& t) {
    addMeans(t);
    if (k_ < 2) return;
    computeUStatistics();
    for (size_t s = 0; s < series_; ++s) t.u[s] += u_[s];
  }

  // Second pass, once the totals give each ratio R_s = A_s / B (K ≥ 4): the variances the intervals and
  // the verdict need, each a quadratic form of the pixel's covariance estimate, added to the pixel's block
  // (block: its ratioVar and diffVar, laid out as Totals'); and the ratio's variance by the jackknife,
  // never negative, for its degrees of freedom (t.jack, t.jackSquared).
  void addVariances(Totals& t, double* ratioVar, double* diffVar) {
    computeUStatistics();
    const double b = t.u[0];
    for (size_t s = 1; s < series_; ++s) {
      const double r = t.u[s] / b;
      ratioVar[s] += (cov(s, s) - 2.0 * r * cov(s, 0) + r * r * cov(0, 0)) / (b * b);
      const double v = (jackknifeCov(s, s) - 2.0 * r * jackknifeCov(s, 0) + r * r * jackknifeCov(0, 0)) / (b * b);
      t.jack[s] += v;
      t.jackSquared[s] += v * v;
      for (size_t q = s + 1; q < series_; ++q) {
        const double v = cov(s, s) + cov(q, q) - 2.0 * cov(s, q);
        diffVar[s * series_ + q] += v;
        diffVar[q * series_ + s] += v;
      }
    }
    addScoreTerms(t);
    for (size_t s = 1; s < series_; ++s) {
      const double ratio = t.lum[s] / t.lum[0];
      double mean = 0.0, var = 0.0;
      for (int j = 0; j < k_; ++j) mean += (l_[s * k_ + j] - ratio * l_[j]) / k_;
      for (int j = 0; j < k_; ++j) var += (l_[s * k_ + j] - ratio * l_[j] - mean) * (l_[s * k_ + j] - ratio * l_[j] - mean);
      const double v = var / (k_ * (k_ - 1.0));
      t.lumRatioVar[s] += v, t.lumRatioVarSquared[s] += v * v;
    }
  }

 private:
  // The replicate means, for the plain figures, and the variance of the luminance means: sample
  // (co)variance / K, as for any mean of K independent values.
  void addMeans(Totals& t) const {
    const double k = k_;
    double lum0 = 0.0;
    for (int j = 0; j < k_; ++j) lum0 += l_[j] / k;
    for (size_t s = 0; s < series_; ++s) {
      Rgb3 mean{};
      double lum = 0.0;
      for (int j = 0; j < k_; ++j) {
        for (int c = 0; c < 3; ++c) mean[c] += x_[s * k_ + j][c] / k;
        lum += l_[s * k_ + j] / k;
      }
      t.squared[s] += dot(mean, mean);
      t.lum[s] += lum;
      if (k_ < 2) continue;
      double var = 0.0, cov = 0.0;
      for (int j = 0; j < k_; ++j) {
        var += (l_[s * k_ + j] - lum) * (l_[s * k_ + j] - lum);
        cov += (l_[s * k_ + j] - lum) * (l_[j] - lum0);
      }
      t.lumVar[s] += var / (k * (k - 1.0));
      t.lumCov[s] += cov / (k * (k - 1.0));
    }
  }

  // U_s = Σ_{j≠k} x_j · x_k / (K (K − 1)), from the Gram matrix of the replicates, kept for the covariances.
  void computeUStatistics() {
    const double k = k_;
    for (size_t s = 0; s < series_; ++s) {
      total_[s] = 0.0;
      for (int j = 0; j < k_; ++j) {
        double row = 0.0;
        for (int i = 0; i < k_; ++i) {
          gram(s, j, i) = dot(x_[s * k_ + j], x_[s * k_ + i]);
          if (i != j) row += gram(s, j, i);
        }
        rowSum_[s * k_ + j] = row;
        total_[s] += row;
      }
      u_[s] = total_[s] / (k * (k - 1.0));
    }
  }

  // Cov(U_f, U_g) = E[U_f U_g] − θ_f θ_g, with θ_f θ_g estimated by the mean of f(a, b) g(c, d) over the
  // K (K − 1) (K − 2) (K − 3) ordered quadruples of distinct replicates. With F_a = Σ_{b≠a} f(a, b) and
  // F = Σ_a F_a, their sum is F G − 4 Σ_a F_a G_a + 2 Σ_{a≠b} f(a, b) g(a, b): all ordered pairs of pairs,
  // less those sharing a replicate.
  double cov(size_t s, size_t r) const {
    const double k = k_, quadruples = k * (k - 1.0) * (k - 2.0) * (k - 3.0);
    double rows = 0.0, pairs = 0.0;
    for (int a = 0; a < k_; ++a) {
      rows += rowSum_[s * k_ + a] * rowSum_[r * k_ + a];
      for (int b = 0; b < k_; ++b)
        if (b != a) pairs += gram(s, a, b) * gram(r, a, b);
    }
    const double products = total_[s] * total_[r] - 4.0 * rows + 2.0 * pairs;
    return u_[s] * u_[r] - products / quadruples;
  }

  // The delete-one-replicate jackknife's (co)variance of U_s and U_r: biased up where noise dominates, but
  // positive semi-definite, so its quadratic forms weigh each pixel's share of a variance. U without
  // replicate a is (F − 2 F_a) / ((K − 1)(K − 2)), F the sum over ordered pairs and F_a replicate a's row.
  double jackknifeCov(size_t s, size_t r) const {
    const double k = k_, norm = (k - 1.0) * (k - 2.0);
    const auto without = [&](size_t q, int a) { return (total_[q] - 2.0 * rowSum_[q * k_ + a]) / norm; };
    double meanS = 0.0, meanR = 0.0;
    for (int a = 0; a < k_; ++a) meanS += without(s, a) / k, meanR += without(r, a) / k;
    double sum = 0.0;
    for (int a = 0; a < k_; ++a) sum += (without(s, a) - meanS) * (without(r, a) - meanR);
    return (k - 1.0) / k * sum;
  }

  // The pieces of Var(U_d − ρ U_m) = 4/K (μ_d − ρ μ_m)-weighted covariance + 2/(K (K − 1)) tr-terms that the
  // test inversion recombines for each ρ: the replicates' deviations projected on the pixel's means, and
  // tr(C Cᵀ) unbiased from disjoint pairs of replicates, E[(Δx·Δx')(Δy·Δy')] = 4 tr(C Cᵀ) for the
  // differences Δ = x_a − x_b, Δ' = x_c − x_e of four distinct replicates.
  void addScoreTerms(Totals& t) {
    const double k = k_;
    std::vector<Rgb3>& mean = mean_;
    std::fill(mean.begin(), mean.end(), Rgb3{});
    for (size_t s = 0; s < series_; ++s)
      for (int j = 0; j < k_; ++j)
        for (int c = 0; c < 3; ++c) mean[s][c] += x_[s * k_ + j][c] / k;
    const auto projection = [&](size_t s, int j) {
      const Rgb3& x = x_[s * k_ + j];
      return dot({x[0] - mean[s][0], x[1] - mean[s][1], x[2] - mean[s][2]}, mean[s]);
    };
    for (size_t s = 0; s < series_; ++s) {
      double var = 0.0, cov = 0.0;
      for (int j = 0; j < k_; ++j) {
        var += projection(s, j) * projection(s, j);
        cov += projection(s, j) * projection(0, j);
      }
      t.projVar[s] += var / (k - 1.0);
      if (s > 0) t.projCov[s] += cov / (k - 1.0);
    }
    double count = 0.0;
    std::vector<double>& trace = trace_;
    std::vector<double>& cross = cross_;
    std::fill(trace.begin(), trace.end(), 0.0);
    std::fill(cross.begin(), cross.end(), 0.0);
    const auto delta = [&](size_t s, int a, int b) {
      const Rgb3 &p = x_[s * k_ + a], &q = x_[s * k_ + b];
      return Rgb3{p[0] - q[0], p[1] - q[1], p[2] - q[2]};
    };
    for (int a = 0; a < k_; ++a)
      for (int b = a + 1; b < k_; ++b)
        for (int c = a + 1; c < k_; ++c)
          for (int e = c + 1; e < k_; ++e) {
            if (c == b || e == b) continue;
            count += 1.0;
            const double m = dot(delta(0, a, b), delta(0, c, e));
            trace[0] += m * m;
            for (size_t s = 1; s < series_; ++s) {
              const double d = dot(delta(s, a, b), delta(s, c, e));
              trace[s] += d * d, cross[s] += d * m;
            }
          }
    for (size_t s = 0; s < series_; ++s) t.trace[s] += trace[s] / (4.0 * count), t.traceCross[s] += cross[s] / (4.0 * count);
  }

  double& gram(size_t s, int j, int i) { return gram_[(s * k_ + j) * k_ + i]; }
  double gram(size_t s, int j, int i) const { return gram_[(s * k_ + j) * k_ + i]; }

  size_t series_;
  int k_;
  std::vector<Rgb3> x_;
  std::vector<double> l_;
  std::vector<double> gram_, rowSum_, total_, u_;
  std::vector<Rgb3> mean_;             // addScoreTerms' scratch, per series, kept to spare an allocation per pixel
  std::vector<double> trace_, cross_;
};

// Below this many Welch–Satterthwaite degrees of freedom a few pixels carry the variance of A, and the
// r* interval is the test inversion's (scoreInterval) instead of the delta method's. Broad lobes, where the
// delta method holds and is narrower, have ν in the hundreds; sharp ones 3–40 (docs/sheets.md).
constexpr double kFewDof = 50.0;

// Below this many, ν is no estimate to lean on: it comes from the same few pixels' K replicates as the
// variance it qualifies, and a seed whose dominant pixel's replicates happen to agree gets a small variance
// and a larger ν at once (docs/sheets.md, "The intervals"). There t takes K − 1 degrees of freedom, the
// fewest a sum over pixels can have.
constexpr double kUnsteadyDof = 10.0;

// The set of ρ ≥ 0 with (R − ρ)² ≤ t² v(ρ), R = A / B and v(ρ) the variance of A / B − ρ were ρ the true
// ratio: an interval not centred on a variance estimated at R itself, which collapses with R where one
// pixel carries A (a seed whose difference there comes out small has a small R and a small variance).
// Its ends by bisection from R outward; an end the test never rejects stays at 0 or at `cap`.
template <class Variance> Interval scoreInterval(double r, double t, double step, double cap, Variance&& v) {
  const auto accepted = [&](double rho) { return (r - rho) * (r - rho) <= t * t * v(rho); };
  const double start = std::max(r, 0.0);
  if (!accepted(start)) return {start, start};  // only when R < 0: then 0 is rejected too
  const auto bisect = [&](double in, double out) {
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (in + out);
      (accepted(mid) ? in : out) = mid;
    }
    return in;
  };
  const double lo = accepted(0.0) ? 0.0 : bisect(start, 0.0);
  if (accepted(cap)) return {lo, std::max(cap, start)};
  double in = start, h = step > 0.0 ? step : std::max(start, 1e-300);
  while (in + h < cap && accepted(in + h)) in += h, h *= 2.0;
  return {lo, bisect(in, std::min(in + h, cap))};
}

// Blocks of kBlock × kBlock pixels, over which the variance estimates are summed before they are clamped.
constexpr size_t kBlock = 16;

// The analytic panels that have images, in order: series 1 + f is panel fitted[f]. Throws where one's
// replicate count differs from the measured panel's or an image's size from the mask's.
std::vector<size_t> fittedPanels(const std::vector<std::vector<RgbImage>>& panels, const std::vector<RgbImage>& measured,
                                 const std::vector<char>& mask) {
  const int k = int(measured.size());
  const auto checkSize = [&](const RgbImage& image) {
    if (image.pixels.size() != 3 * mask.size())
      throw std::invalid_argument("compareToMeasured: an image's size differs from the mask's");
  };
  std::vector<size_t> fitted;
  for (size_t p = 0; p < panels.size(); ++p) {
    if (panels[p].empty()) continue;
    if (int(panels[p].size()) != k)
      throw std::invalid_argument("compareToMeasured: panel " + std::to_string(p) + " has " +
                                  std::to_string(panels[p].size()) + " replicates, the measured panel " +
                                  std::to_string(k));
    for (const RgbImage& image : panels[p]) checkSize(image);
    fitted.push_back(p);
  }
  for (const RgbImage& image : measured) checkSize(image);
  return fitted;
}

// What compareToMeasured compares: the measured panel's replicates and those of the panels in `fitted`.
struct Inputs {
  const std::vector<std::vector<RgbImage>>& panels;
  const std::vector<RgbImage>& measured;
  const std::vector<char>& mask;
  const std::vector<size_t>& fitted;
};

// Each compared pixel's replicates into `pixel`, then f(i); the compared and skipped pixels counted into
// `counts` when given (on one pass only: every pass sees the same pixels).
template <class F> void forEachPixel(const Inputs& in, PixelReplicates& pixel, Comparison* counts, F&& f) {
  const int k = int(in.measured.size());
  const auto rgb = [](const RgbImage& image, size_t i) {
    return Rgb3{image.pixels[3 * i], image.pixels[3 * i + 1], image.pixels[3 * i + 2]};
  };
  const auto lum = [](const Rgb3& v) { return luminance(Rgb(v[0], v[1], v[2])); };
  for (size_t i = 0; i < in.mask.size(); ++i) {
    if (!in.mask[i]) continue;
    for (int j = 0; j < k; ++j) {
      const Rgb3 m = rgb(in.measured[j], i);
      pixel.x(0, j) = m;
      pixel.l(0, j) = lum(m);
      for (size_t f = 0; f < in.fitted.size(); ++f) {
        const Rgb3 p = rgb(in.panels[in.fitted[f]][j], i);
        pixel.x(1 + f, j) = {p[0] - m[0], p[1] - m[1], p[2] - m[2]};
        pixel.l(1 + f, j) = lum(p);
      }
    }
    // Finite floats give finite differences, products and sums in double: checking the inputs suffices.
    if (!pixel.finite()) {
      if (counts) ++counts->skippedPixels;
      continue;
    }
    if (counts) ++counts->pixels;
    f(i);
  }
}

// The second pass (K ≥ 4, B > 0): the variances of the intervals and the verdict into `totals`.
void addBlockVariances(const Inputs& in, PixelReplicates& pixel, Totals& totals) {
  // The variances are summed per block of kBlock² pixels, each block's clamped at 0. The per-pixel
  // estimate is unbiased but not always positive semi-definite: one bright outlier among a pixel's
  // replicates can make a form hugely negative and cancel the spread of every other pixel (seen as
  // zero-width intervals). A block's sum averages out the ordinary sign flips of noise-dominated pixels,
  // which a per-pixel clamp would turn into a large overstatement, and confines an outlier to its block.
  const size_t series = totals.series;
  const int width = in.measured.front().width, blocksX = (width + kBlock - 1) / kBlock;
  const size_t height = in.mask.size() / size_t(std::max(width, 1)), blocks = size_t(blocksX) * ((height + kBlock - 1) / kBlock);
  std::vector<double> ratioVar(blocks * series), diffVar(blocks * series * series);
  forEachPixel(in, pixel, nullptr, [&](size_t i) {
    const size_t block = (i / size_t(width)) / kBlock * size_t(blocksX) + (i % size_t(width)) / kBlock;
    pixel.addVariances(totals, &ratioVar[block * series], &diffVar[block * series * series]);
  });
  for (size_t b = 0; b < blocks; ++b) {
    for (size_t s = 0; s < series; ++s) totals.ratioVar[s] += std::max(0.0, ratioVar[b * series + s]);
    for (size_t e = 0; e < series * series; ++e) totals.diffVar[e] += std::max(0.0, diffVar[b * series * series + e]);
  }
}

// Both passes over the compared pixels; the first counts them into `out`.
Totals sumOverPixels(const Inputs& in, Comparison& out) {
  const int k = int(in.measured.size());
  Totals totals(1 + in.fitted.size());
  PixelReplicates pixel(totals.series, k);
  forEachPixel(in, pixel, &out, [&](size_t) { pixel.addTo(totals); });
  if (k >= 4 && totals.u[0] > 0.0) addBlockVariances(in, pixel, totals);
  return totals;
}

// The r* interval where few pixels carry A (ν < kFewDof): the delta method's variance, taken at this
// seed's own difference, shrinks with it. Test each ρ with the variance A would have if the true squared
// difference were ρ B: the difference terms scaled by c² = ρ B / Σ|d̄|² (the seed's differences give the
// pixels' shares and directions, ρ their size); the noise-only terms, which may come out negative, clamped
// at 0.
Interval invertedTestInterval(const Totals& totals, size_t s, int k, double ratio, double tq, double halfRatio) {
  const double b = totals.u[0];
  const double kk = k, sd = totals.squared[s];
  const auto variance = [&](double rho) {
    const double c = sd > 0.0 ? std::sqrt(rho * b / sd) : 0.0;
    const double linear = c * c * totals.projVar[s] - 2.0 * rho * c * totals.projCov[s] + rho * rho * totals.projVar[0];
    const double noise = totals.trace[s] - 2.0 * rho * totals.traceCross[s] + rho * rho * totals.trace[0];
    return (4.0 / kk * linear + std::max(0.0, 2.0 / (kk * (kk - 1.0)) * noise)) / (b * b);
  };
  // Where B's own variance is as large as (B / t)² (a highlight seen in one replicate of the measured
  // panel) no ρ above R is rejected: the interval then ends at four times the noisy figure's square
  // (twice the noisy r), finite, since studies and merged tables take only finite bounds.
  const double cap = 4.0 * std::max(ratio + halfRatio, totals.squared[s] / totals.squared[0]);
  const Interval squared = scoreInterval(ratio, tq, halfRatio, cap, variance);
  return {std::sqrt(squared.lo), std::sqrt(squared.hi)};
}

// Panel series s's r* interval and its degrees of freedom, R = A / B being `ratio` (K ≥ 4).
// Welch–Satterthwaite: a sum of per-pixel variances, each from K − 1 degrees of freedom, has
// ν = (K − 1) (Σ v)² / Σ v² of them, few when a handful of pixels carry the variance (a sharp highlight
// a few pixels wide, a rare bright path): an interval then takes Student's t for ν, not the normal z.
double welchDof(double sum, double sumSquared, int k) {
  return sumSquared > 0.0 ? (k - 1.0) * sum * sum / sumSquared : std::numeric_limits<double>::infinity();
}

// Student's t for ν degrees of freedom; for K − 1 below kUnsteadyDof, where ν is as unsteady as the variance.
double tQuantile(double confidence, double dof, int k) { return studentQuantile(confidence, dof < kUnsteadyDof ? k - 1.0 : dof); }

void setRelativeRmseCi(PanelFigures& fig, const Totals& totals, size_t s, int k, double ratio, double confidence) {
  fig.relativeRmseDof = welchDof(totals.jack[s], totals.jackSquared[s], k);
  const double tq = tQuantile(confidence, fig.relativeRmseDof, k);
  const double halfRatio = tq * std::sqrt(totals.ratioVar[s]);
  fig.relativeRmseCi = {std::sqrt(std::max(0.0, ratio - halfRatio)), std::sqrt(std::max(0.0, ratio + halfRatio))};
  if (fig.relativeRmseDof < kFewDof) fig.relativeRmseCi = invertedTestInterval(totals, s, k, ratio, tq, halfRatio);
  // Every ρ ≥ 0 rejected: A came out further below 0 than its estimated noise allows, so that noise is
  // underestimated (a bright path in one replicate of one pixel), and no value is known to be excluded.
  // Up to twice the noisy figure, as where nothing above R is rejected, rather than the empty [0, 0].
  if (!(fig.relativeRmseCi.hi > 0.0)) fig.relativeRmseCi = {0.0, 2.0 * fig.noisyRelativeRmse};
}

// Panel series s's luminance ratio interval, by the delta method on Σ lum(p̄) / Σ lum(m̄) (K ≥ 4).
Interval luminanceRatioCi(const PanelFigures& fig, const Totals& totals, size_t s, int k, double confidence) {
  const double l = fig.luminanceRatio, lumTotal = totals.lum[0];
  const double varL = (totals.lumVar[s] - 2.0 * l * totals.lumCov[s] + l * l * totals.lumVar[0]) / (lumTotal * lumTotal);
  // Student's t for the luminance sums too, with their own degrees of freedom: a highlight's few pixels
  // carry their variance as they carry A's.
  const double lumDof = welchDof(totals.lumRatioVar[s], totals.lumRatioVarSquared[s], k);
  const double halfL = tQuantile(confidence, lumDof, k) * std::sqrt(std::max(0.0, varL));
  return {l - halfL, l + halfL};
}

// Panel series s's figures, as far as K allows, the measured panel having signal over the mask.
void setFigures(PanelFigures& fig, const Totals& totals, size_t s, int k, double confidence) {
  const double b = totals.u[0];
  fig.noisyRelativeRmse = std::sqrt(totals.squared[s] / totals.squared[0]);
  fig.luminanceRatio = totals.lum[s] / totals.lum[0];

  fig.available = k >= 2 && b > 0.0;
  if (!fig.available) return;
  const double a = totals.u[s], ratio = a / b;
  fig.squaredError = a;
  fig.clamped = a < 0.0;
  fig.relativeRmse = std::sqrt(std::max(0.0, ratio));

  fig.hasCi = k >= 4;
  if (!fig.hasCi) return;
  setRelativeRmseCi(fig, totals, s, k, ratio, confidence);
  fig.luminanceRatioCi = luminanceRatioCi(fig, totals, s, k, confidence);
}

std::string percent(double confidence) {
  std::ostringstream s;
  s << confidence * 100.0 << " %";
  return s.str();
}

// fitted[f]: the panel of series 1 + f.
Verdict decide(const Comparison& out, const std::vector<size_t>& fitted, const Totals& t, double z, double confidence) {
  if (out.pixels == 0) return {{}, "no verdict: no pixels to compare"};
  if (fitted.empty()) return {{}, "no verdict: no model panel"};
  if (!out.panels[fitted.front()].compared) return {{}, "no verdict: the measured panel is black over the mask"};
  if (out.replicates < 4) return {{}, "no verdict: fewer than 4 replicates"};
  if (!out.panels[fitted.front()].available) return {{}, "no verdict: the measured panel is below its noise"};
  if (fitted.size() == 1) return {{fitted.front()}, "closest: the only model panel"};

  size_t best = 0;
  for (size_t f = 1; f < fitted.size(); ++f)
    if (t.u[1 + f] < t.u[1 + best]) best = f;
  std::vector<size_t> tied = {best};
  for (size_t f = 0; f < fitted.size(); ++f) {
    if (f == best) continue;
    const size_t q = 1 + f, b = 1 + best;
    const double sd = std::sqrt(t.diff(q, b));
    if (!(t.u[q] - t.u[b] > z * sd)) tied.push_back(f);
  }
  std::sort(tied.begin() + 1, tied.end(), [&](size_t f, size_t g) { return t.u[1 + f] < t.u[1 + g]; });

  std::ostringstream zText;
  zText.precision(3);
  zText << z;
  Verdict v;
  for (size_t f : tied) v.models.push_back(fitted[f]);
  v.why = tied.size() == 1 ? "closest: every other model's squared error is larger by more than " + zText.str() +
                                 " standard errors (" + percent(confidence) + " confidence)"
                           : "tie: these models' squared errors are within " + zText.str() +
                                 " standard errors of the smallest (" + percent(confidence) + " confidence)";
  return v;
}

}  // namespace

double Comparison::widestHalfWidth() const {
  double widest = -1.0;
  for (const PanelFigures& p : panels)
    if (p.hasCi) widest = std::max(widest, p.relativeRmseCi.halfWidth());
  return widest < 0.0 ? std::numeric_limits<double>::infinity() : widest;
}

Comparison compareToMeasured(const std::vector<std::vector<RgbImage>>& panels, const std::vector<RgbImage>& measured,
                             const std::vector<char>& mask, double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0))
    throw std::invalid_argument("compareToMeasured: confidence must be in (0, 1)");
  Comparison out;
  out.panels.resize(panels.size());
  if (measured.empty()) {
    out.verdict.why = "no verdict: no measured panel";
    return out;
  }
  const int k = int(measured.size());
  const std::vector<size_t> fitted = fittedPanels(panels, measured, mask);
  out.replicates = k;

  const Totals totals = sumOverPixels({panels, measured, mask, fitted}, out);
  const double z = twoSidedQuantile(confidence);
  const bool signal = out.pixels > 0 && totals.squared[0] > 0.0 && totals.lum[0] > 0.0;
  out.measuredSquared = totals.u[0];
  for (size_t f = 0; f < fitted.size(); ++f) {
    PanelFigures& fig = out.panels[fitted[f]];
    fig.compared = signal;
    if (fig.compared) setFigures(fig, totals, 1 + f, k, confidence);
  }
  out.verdict = decide(out, fitted, totals, z, confidence);
  return out;
}

}  // namespace glossy
