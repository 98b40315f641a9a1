// Piecewise-constant 1D and 2D distributions: CDF construction and inversion.
#include "materials/sampling/distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

// The largest double below 1: the top of every sampled range, so callers can index with ⌊x·n⌋.
constexpr double kOneMinusEpsilon = 1.0 - 0x1p-53;

double clampUnit(double u) {
  // NaN goes to 0 rather than propagating into an index.
  return u >= 0.0 ? std::min(u, kOneMinusEpsilon) : 0.0;
}

// First CDF entry above u, minus one: cdf[i] ≤ u < cdf[i+1], which skips zero-width (zero-weight) bins.
std::size_t searchBin(std::span<const double> cdf, double u) {
  const auto above = std::upper_bound(cdf.begin(), cdf.end(), u);
  const auto bin = std::size_t(std::max<std::ptrdiff_t>(above - cdf.begin() - 1, 0));
  return std::min(bin, cdf.size() - 2);
}
}  // namespace

Distribution1D::Distribution1D(std::span<const double> values) : values_(values.begin(), values.end()) {
  if (values_.empty()) throw std::invalid_argument("Distribution1D: no bins");
  for (double v : values_)
    if (!(v >= 0.0) || !std::isfinite(v)) throw std::invalid_argument("Distribution1D: negative or non-finite bin");

  const std::size_t n = values_.size();
  cdf_.resize(n + 1);
  cdf_[0] = 0.0;
  for (std::size_t i = 0; i < n; ++i) cdf_[i + 1] = cdf_[i] + values_[i];
  const double sum = cdf_[n];
  integral_ = sum / double(n);
  if (sum > 0.0) {
    for (std::size_t i = 1; i < n; ++i) cdf_[i] /= sum;
  } else {
    for (std::size_t i = 1; i < n; ++i) cdf_[i] = double(i) / double(n);
  }
  // Exactly 1 regardless of rounding in the sum, so any u < 1 finds a bin.
  cdf_[n] = 1.0;
  guide_.resize(n);
  for (std::size_t k = 0; k < n; ++k) guide_[k] = uint32_t(searchBin(cdf_, double(k) / double(n)));
}

std::size_t Distribution1D::binOf(double u) const {
  const std::size_t n = values_.size();
  std::size_t k = std::min(std::size_t(u * double(n)), n - 1);
  // u·n may round into a neighbouring guide cell; the cell must satisfy k/n ≤ u < (k+1)/n exactly.
  while (k > 0 && double(k) / double(n) > u) --k;
  while (k + 1 < n && double(k + 1) / double(n) <= u) ++k;
  // The answer lies between this guide cell's first bin and the next cell's; a binary search there stays
  // short even where many nearly empty bins share one cell (the dark part of a map with a bright sun).
  const std::size_t lo = guide_[k], hi = k + 1 < n ? guide_[k + 1] : n - 1;
  const auto above = std::upper_bound(cdf_.begin() + std::ptrdiff_t(lo) + 1, cdf_.begin() + std::ptrdiff_t(hi) + 1, u);
  return std::size_t(above - cdf_.begin()) - 1;
}

double Distribution1D::density(std::size_t bin) const {
  return integral_ > 0.0 ? values_[bin] / integral_ : 1.0;
}

double Distribution1D::sampleContinuous(double u, double* pdf, std::size_t* offset) const {
  u = clampUnit(u);
  const std::size_t bin = binOf(u);
  const double width = cdf_[bin + 1] - cdf_[bin];
  double du = width > 0.0 ? (u - cdf_[bin]) / width : 0.0;
  du = std::clamp(du, 0.0, kOneMinusEpsilon);

  const double n = double(values_.size());
  double x = (double(bin) + du) / n;
  // Rounding in (bin + du)/n can step into a neighbouring bin; pull x back so that pdf(x) and the bin
  // reported here always agree.
  while (x * n >= double(bin + 1)) x = std::nextafter(x, 0.0);
  while (x * n < double(bin)) x = std::nextafter(x, 1.0);

  if (pdf) *pdf = density(bin);
  if (offset) *offset = bin;
  return x;
}

std::size_t Distribution1D::sampleDiscrete(double u, double* probability) const {
  const std::size_t bin = binOf(clampUnit(u));
  if (probability) *probability = discreteProbability(bin);
  return bin;
}

double Distribution1D::pdf(double x) const {
  if (!(x >= 0.0 && x <= 1.0)) return 0.0;
  const std::size_t bin = std::min(std::size_t(x * double(values_.size())), values_.size() - 1);
  return density(bin);
}

double Distribution1D::discreteProbability(std::size_t bin) const {
  return integral_ > 0.0 ? values_[bin] / (integral_ * double(values_.size())) : 1.0 / double(values_.size());
}

Distribution2D::Distribution2D(std::span<const double> values, std::size_t width, std::size_t height) {
  if (width == 0 || height == 0 || values.size() != width * height)
    throw std::invalid_argument("Distribution2D: table size does not match width × height");
  conditional_.reserve(height);
  std::vector<double> rowIntegrals(height);
  for (std::size_t y = 0; y < height; ++y) {
    conditional_.emplace_back(values.subspan(y * width, width));
    rowIntegrals[y] = conditional_.back().integral();
  }
  marginal_ = Distribution1D(rowIntegrals);
}

Distribution2D::Sample Distribution2D::sample(Vec2 u) const {
  double pdfRow = 0.0, pdfInRow = 0.0;
  std::size_t row = 0;
  const double y = marginal_.sampleContinuous(u.y, &pdfRow, &row);
  const double x = conditional_[row].sampleContinuous(u.x, &pdfInRow);
  return {Vec2(x, y), pdfRow * pdfInRow};
}

double Distribution2D::pdf(Vec2 point) const {
  if (!(point.x >= 0.0 && point.x <= 1.0 && point.y >= 0.0 && point.y <= 1.0)) return 0.0;
  const std::size_t row = std::min(std::size_t(point.y * double(height())), height() - 1);
  // The same product, in the same order, as sample(), so the two agree to the last bit.
  return marginal_.pdf(point.y) * conditional_[row].pdf(point.x);
}

}  // namespace glossy
