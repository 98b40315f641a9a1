// Piecewise-constant 1D and 2D distributions: CDF construction and inversion.
#include "materials/sampling/distribution.h"

#include "materials/sampling/unit_interval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

// First CDF entry above u, minus one: cdf[i] ≤ u < cdf[i+1], which skips zero-width (zero-weight) bins.
std::size_t searchBin(std::span<const double> cdf, double u) {
  const auto above = std::upper_bound(cdf.begin(), cdf.end(), u);
  const auto bin = std::size_t(std::max<std::ptrdiff_t>(above - cdf.begin() - 1, 0));
  return std::min(bin, cdf.size() - 2);
}

// Normalises the running sums in cdf (n + 1 entries, cdf[0] = 0, cdf[n] = the sum) and fills the guide
// table (n entries): guide[k] = searchBin(k/n).
void finishCdf(std::span<double> cdf, std::span<uint32_t> guide) {
  const std::size_t n = cdf.size() - 1;
  const double sum = cdf[n];
  if (sum > 0.0) {
    for (std::size_t i = 1; i < n; ++i) cdf[i] /= sum;
  } else {
    for (std::size_t i = 1; i < n; ++i) cdf[i] = double(i) / double(n);
  }
  // Exactly 1 regardless of rounding in the sum, so any u < 1 finds a bin.
  cdf[n] = 1.0;
  for (std::size_t k = 0; k < n; ++k) guide[k] = uint32_t(searchBin(cdf, double(k) / double(n)));
}

// searchBin(cdf, u) for u in [0,1), from the guide table: the same bin, found by stepping from the guide
// entry of u's cell. Each cell spans 1/n of u, so a uniform u meets on average about two bins per cell and
// the scan stays O(1) expected; a cell with many (nearly empty) bins is bisected first, which bounds the
// worst case. The steps back and forth make the answer exact even where u·n rounds into the next cell.
std::size_t findBin(const double* cdf, const uint32_t* guide, std::size_t n, double u) {
  const std::size_t k = std::min(std::size_t(u * double(n)), n - 1);
  std::size_t bin = guide[k];
  const std::size_t next = k + 1 < n ? guide[k + 1] : n - 1;
  if (next - bin > 8) bin = std::size_t(std::upper_bound(cdf + bin + 1, cdf + next + 1, u) - cdf) - 1;
  while (bin > 0 && cdf[bin] > u) --bin;
  while (cdf[bin + 1] <= u) ++bin;  // ends by cdf[n] = 1 > u
  return bin;
}

// The x in bin `bin` of n with P(X < x) = u, the CDF being linear within the bin.
double invertInBin(const double* cdf, std::size_t n, std::size_t bin, double u) {
  const double width = cdf[bin + 1] - cdf[bin];
  double du = width > 0.0 ? (u - cdf[bin]) / width : 0.0;
  return pointInBin(bin, std::clamp(du, 0.0, kOneMinusEpsilon), n);  // so that pdf(x) agrees with the bin
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
  integral_ = cdf_[n] / double(n);
  guide_.resize(n);
  finishCdf(cdf_, guide_);
}

std::size_t Distribution1D::binOf(double u) const {
  return findBin(cdf_.data(), guide_.data(), values_.size(), u);
}

double Distribution1D::density(std::size_t bin) const {
  return integral_ > 0.0 ? values_[bin] / integral_ : 1.0;
}

double Distribution1D::sampleContinuous(double u, double* pdf, std::size_t* offset) const {
  u = clampUnit(u);
  const std::size_t bin = binOf(u);
  const double x = invertInBin(cdf_.data(), values_.size(), bin, u);
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

Distribution2D::Distribution2D(std::span<const double> values, std::size_t width, std::size_t height)
    : width_(width) {
  if (width == 0 || height == 0 || values.size() != width * height)
    throw std::invalid_argument("Distribution2D: table size does not match width × height");
  for (double v : values)
    if (!(v >= 0.0) || !std::isfinite(v)) throw std::invalid_argument("Distribution2D: negative or non-finite value");
  cdf_.resize(height * (width + 1));
  guide_.resize(height * width);
  std::vector<double> rowIntegrals(height);
  for (std::size_t y = 0; y < height; ++y) {
    const std::span<double> cdf(&cdf_[y * (width + 1)], width + 1);
    cdf[0] = 0.0;
    for (std::size_t x = 0; x < width; ++x) cdf[x + 1] = cdf[x] + values[y * width + x];
    rowIntegrals[y] = cdf[width] / double(width);
    finishCdf(cdf, std::span<uint32_t>(&guide_[y * width], width));
  }
  marginal_ = Distribution1D(rowIntegrals);

  // What pdfRow · pdfInRow of the two 1D densities was, stored: the same product in the same order.
  density_.resize(height * width);
  for (std::size_t y = 0; y < height; ++y) {
    const double pdfRow = marginal_.pdf((double(y) + 0.5) / double(height));
    for (std::size_t x = 0; x < width; ++x) {
      const double pdfInRow = rowIntegrals[y] > 0.0 ? values[y * width + x] / rowIntegrals[y] : 1.0;
      density_[y * width + x] = pdfRow * pdfInRow;
    }
  }
}

Distribution2D::Sample Distribution2D::sample(Vec2 u) const {
  std::size_t row = 0;
  const double y = marginal_.sampleContinuous(u.y, nullptr, &row);
  const double ux = clampUnit(u.x);
  const double* cdf = &cdf_[row * (width_ + 1)];
  const std::size_t column = findBin(cdf, &guide_[row * width_], width_, ux);
  return {Vec2(invertInBin(cdf, width_, column, ux), y), cellDensity(column, row), column, row};
}

double Distribution2D::pdf(Vec2 point) const {
  if (!(point.x >= 0.0 && point.x <= 1.0 && point.y >= 0.0 && point.y <= 1.0)) return 0.0;
  const std::size_t row = std::min(std::size_t(point.y * double(height())), height() - 1);
  const std::size_t column = std::min(std::size_t(point.x * double(width_)), width_ - 1);
  return cellDensity(column, row);
}

}  // namespace glossy
