// How close each analytic panel of a material sheet comes to the measured panel, with the render noise
// taken out, 95 % confidence intervals, and a verdict on which model is closest.
//
// Every panel is rendered as K independent replicates, each the mean of its own samples; replicate j of
// every panel uses the same random numbers (coherent rendering), so the difference of two panels is less
// noisy than either. The plain figure ‖p̄ − m̄‖ / ‖m̄‖ is biased upward: E‖p̄ − m̄‖² = ‖P − M‖² + the noise
// variance of p̄ − m̄. A product of two *different* replicates has no such term, their noise being
// independent: E[d_j · d_k] = |P − M|² for j ≠ k, with d = p − m the RGB difference of a pixel. Hence
//   A = Σ_pixels U(d),  U(d) = Σ_{j≠k} d_j · d_k / (K (K − 1))   (the U-statistic over replicate pairs)
// is unbiased for ‖P − M‖², B = Σ_pixels U(m) likewise for ‖M‖², and r* = √(A / B) is the relative RMSE
// without the noise floor (A can come out negative when P ≈ M: r* is then 0, flagged `clamped`).
//
// Uncertainty. Pixels are independent of one another (each has its own samples), so the variance of a sum
// over pixels is the sum of the per-pixel variances, each estimated from that pixel's K replicates.
// Resampling blocks of pixels instead would count the spatial variation of the true error as noise and
// give intervals far too wide. Per pixel, the (co)variance of two U-statistics is estimated without bias as
//   Cov(U_f, U_g) = U_f U_g − (the U-statistic of f(j, k) g(l, n) over four distinct replicates),
// which needs K ≥ 4. The delete-one-replicate jackknife would work from K = 3 but overstates the part of the
// variance that is pure noise (the σ⁴ term) by 2 (K − 1) / (K − 2), threefold at K = 4: where the noise of
// a pixel is comparable to its error or larger, as in a sheet at moderate sample counts, its 95 % intervals
// cover about 99 %. That unbiased estimate is not always positive semi-definite: one bright outlier among a
// pixel's replicates can make a variance hugely negative and cancel the spread of every other pixel. So the
// variance each interval and each verdict comparison needs is summed over 16 × 16-pixel blocks and each
// block's sum clamped at 0 (comparison.cpp says why blocks), which can only widen the intervals.
// Intervals follow by the delta method on the ratios (R = A / B: Var R ≈ (Var A − 2R Cov(A, B) + R² Var B) / B²;
// the r* interval is the square root of R's, clamped at 0, so it is asymmetric). R's takes Student's t with
// the Welch–Satterthwaite degrees of freedom of its sum over pixels (each pixel's share weighed by the
// jackknife, which is never negative): where one sharp highlight's few pixels carry the variance, the
// estimate of that variance rests on a few times K − 1 values and z would understate the spread. There
// (ν < 50) the r* interval inverts a test instead: each candidate ρ is tested with the variance A would have
// if the true squared difference were ρ B, not the variance at the seed's own difference, which shrinks
// with it (docs/sheets.md, "The intervals"). The luminance ratio's interval takes t for its own ν. Below
// ν = 10 both take K − 1 degrees of freedom instead: so few rest on a handful of pixels' replicates, which
// set ν and the variance together.
//
// Verdict: all panels share B, so the smallest A is the smallest r*. That model is named closest only if
// every other model's A exceeds it by more than z standard errors of the difference (estimated per pixel
// like the rest, so the correlation of coherent panels narrows it); otherwise it ties with those it is
// not separated from.
#pragma once

#include "renderer/image/exr_image.h"

#include <cstddef>
#include <string>
#include <vector>

namespace glossy {

struct Interval {
  double lo = 0.0, hi = 0.0;
  double halfWidth() const { return 0.5 * (hi - lo); }  // for labels: "0.12 ± 0.01"
};

struct PanelFigures {
  bool compared = false;            // the panel has images and the measured panel has signal over the mask
  double noisyRelativeRmse = 0.0;   // ‖p̄ − m̄‖ / ‖m̄‖, noise included (set when compared)
  double luminanceRatio = 0.0;      // Σ lum(p̄) / Σ lum(m̄) (set when compared)

  bool available = false;           // r* exists: compared, K ≥ 2 and B > 0
  double squaredError = 0.0;        // A, unbiased for Σ |P − M|² over the pixels and channels
  double relativeRmse = 0.0;        // r* = √(max(0, A / B))
  bool clamped = false;             // A < 0: r* is 0 by clamping

  bool hasCi = false;               // available and K ≥ 4
  Interval relativeRmseCi, luminanceRatioCi;
  // The r* interval's degrees of freedom (Welch–Satterthwaite over the pixels); few say that a handful of
  // pixels carry its variance and that the interval may be too narrow (set with hasCi).
  double relativeRmseDof = 0.0;
};

struct Verdict {
  // Indices into the panels: one = the closest model, several = a tie (smallest A first), none = no verdict.
  std::vector<size_t> models;
  std::string why;
};

struct Comparison {
  std::vector<PanelFigures> panels;  // as the analytic panels were given
  Verdict verdict;
  int replicates = 0;                // K
  double measuredSquared = 0.0;      // B, unbiased for Σ |M|² over the pixels and channels (K ≥ 2)
  size_t pixels = 0;                 // masked pixels the figures are over
  size_t skippedPixels = 0;          // masked pixels left out: a value not finite in some replicate of some panel

  // The widest r* interval's half-width over the panels that have one; +∞ when none has (K < 4, no signal):
  // what a loop refining the render until the figures are known to a given precision compares.
  double widestHalfWidth() const;
};

// panels[p]: the K replicates of analytic panel p, or none (no fit: no figures, not in the verdict);
// measured: the K replicates of the measured panel (none: no figures). Every image has one value per mask
// entry; mask: nonzero for the pixels the figures are over (all three channels count). A masked pixel with
// a value that is not finite in any replicate of any panel is skipped for every panel and counted.
// Throws std::invalid_argument when a panel's replicate count differs from the measured one's, an image's
// size from the mask's, or confidence is not in (0, 1).
Comparison compareToMeasured(const std::vector<std::vector<RgbImage>>& panels, const std::vector<RgbImage>& measured,
                             const std::vector<char>& mask, double confidence = 0.95);

}  // namespace glossy
