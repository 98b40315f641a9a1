// BlockedDistribution2D: building the two-level CDFs, and inverting them.
#include "materials/sampling/blocked_distribution.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

constexpr double kOneMinusEpsilon = 1.0 - 0x1p-53;

double clampUnit(double u) { return u >= 0.0 ? std::min(u, kOneMinusEpsilon) : 0.0; }

}  // namespace

BlockedDistribution2D::BlockedDistribution2D(std::span<const double> values, std::size_t width, std::size_t height)
    : width_(width), blocksPerRow_((width + kBlock - 1) / kBlock), cdfStride_(std::bit_ceil(blocksPerRow_) + 1) {
  if (width == 0 || height == 0 || values.size() != width * height)
    throw std::invalid_argument("BlockedDistribution2D: table size does not match width × height");
  for (double v : values)
    if (!(v >= 0.0) || !std::isfinite(v))
      throw std::invalid_argument("BlockedDistribution2D: negative or non-finite value");

  const std::size_t blocks = blocksPerRow_;
  // Each row's CDF is padded with 1s to a power of two of blocks (plus its end), for findBlock.
  blockCdf_.assign(height * cdfStride_, 1.0);
  blocks_.resize(height * blocks);
  std::vector<double> rowSums(height), weights(width);
  for (std::size_t y = 0; y < height; ++y) {
    const double* row = &values[y * width];
    double sum = 0.0;
    for (std::size_t x = 0; x < width; ++x) sum += row[x];
    rowSums[y] = sum;
    // A row with no weight is drawn only from an all-zero table, which is uniform: its cells weigh alike.
    for (std::size_t x = 0; x < width; ++x) weights[x] = sum > 0.0 ? row[x] : 1.0;

    double* cdf = &blockCdf_[y * cdfStride_];
    cdf[0] = 0.0;
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t first = b * kBlock, cells = std::min(kBlock, width - first);
      double blockSum = 0.0;
      for (std::size_t k = 0; k < cells; ++k) blockSum += weights[first + k];
      cdf[b + 1] = cdf[b] + blockSum;

      // Every cell with weight gets one 1/kScale share, the rest are shared out in proportion to the
      // weights (by rounding the running sum, so they add up exactly). A block without weight is never
      // drawn; its shares are anything valid.
      uint16_t* start = blocks_[y * blocks + b].start;
      std::size_t withWeight = 0;
      for (std::size_t k = 0; k < cells; ++k) withWeight += weights[first + k] > 0.0 ? 1 : 0;
      const double spare = double(kScale - withWeight);
      double running = 0.0;
      std::size_t before = 0;
      for (std::size_t k = 0; k < kBlock; ++k) {
        if (k >= cells) {
          start[k] = uint16_t(kScale);  // past the row's end: no share
          continue;
        }
        start[k] = blockSum > 0.0 ? uint16_t(before + std::llround(spare * (running / blockSum)))
                                  : uint16_t(k * kScale / cells);
        running += weights[first + k];
        before += weights[first + k] > 0.0 ? 1 : 0;
      }
    }
    // Normalised, with the last entry exactly 1 so that any u < 1 finds a block.
    const double total = cdf[blocks];
    for (std::size_t b = 1; b < blocks; ++b) cdf[b] /= total;
    cdf[blocks] = 1.0;
  }
  marginal_ = Distribution1D(rowSums);
}

double BlockedDistribution2D::cellDensity(std::size_t column, std::size_t row) const {
  const std::size_t b = column / kBlock, k = column % kBlock;
  const double* cdf = &blockCdf_[row * cdfStride_];
  const uint16_t* start = block(row, b).start;
  const uint32_t upper = k + 1 < kBlock ? start[k + 1] : kScale;
  const double rowDensity = marginal_.pdf((double(row) + 0.5) / double(height()));
  return rowDensity * (cdf[b + 1] - cdf[b]) * (double(upper - start[k]) / kScale) * double(width_);
}

double BlockedDistribution2D::pdf(Vec2 point) const {
  if (!(point.x >= 0.0 && point.x <= 1.0 && point.y >= 0.0 && point.y <= 1.0)) return 0.0;
  const std::size_t row = std::min(std::size_t(point.y * double(height())), height() - 1);
  const std::size_t column = std::min(std::size_t(point.x * double(width_)), width_ - 1);
  return cellDensity(column, row);
}

std::size_t BlockedDistribution2D::findBlock(std::size_t row, double u, double& within) const {
  const double* cdf = &blockCdf_[row * cdfStride_];
  // The last b with cdf[b] ≤ u (cdf[0] = 0), by halving without branches: then u < cdf[b + 1], so a block
  // without weight (no width) is stepped over, and so is the padding (1 > u).
  std::size_t b = 0;
  for (std::size_t step = (cdfStride_ - 1) / 2; step > 0; step /= 2) b += cdf[b + step] <= u ? step : 0;
  const double position = (u - cdf[b]) / (cdf[b + 1] - cdf[b]) * kScale;
  within = std::clamp(position, 0.0, std::nextafter(double(kScale), 0.0));
  return b;
}

void BlockedDistribution2D::finish(std::size_t row, std::size_t b, double within, Sample& s) const {
  const uint16_t* start = block(row, b).start;
  // The last k with start[k] ≤ within (start[0] = 0), by halving 32 without branches: its share then
  // reaches past within, so a cell without a share is never the answer.
  std::size_t k = 0;
  for (std::size_t step = kBlock / 2; step > 0; step /= 2) k += start[k + step] <= within ? step : 0;
  const double lower = start[k], upper = k + 1 < kBlock ? start[k + 1] : kScale;
  const double fraction = std::clamp((within - lower) / (upper - lower), 0.0, kOneMinusEpsilon);
  const std::size_t column = b * kBlock + k;
  const double cells = double(width_);
  double x = (double(column) + fraction) / cells;
  // Rounding in (column + fraction) / n can step into a neighbouring cell; keep x in the one reported.
  while (x * cells >= double(column + 1)) x = std::nextafter(x, 0.0);
  while (x * cells < double(column)) x = std::nextafter(x, 1.0);
  s.point.x = x;
  s.column = column;
}

BlockedDistribution2D::Sample BlockedDistribution2D::sample(Vec2 u) const {
  Sample s;
  s.point.y = marginal_.sampleContinuous(u.y, nullptr, &s.row);
  double within = 0.0;
  const std::size_t b = findBlock(s.row, clampUnit(u.x), within);
  finish(s.row, b, within, s);
  return s;
}

void BlockedDistribution2D::sample(const bool* want, const Vec2* u, Sample* out, int n) const {
  std::size_t blockOf[kMaxBatch];
  double within[kMaxBatch];
  // The marginal and the rows' block CDFs are small and stay cached; the block is the miss.
  for (int i = 0; i < n; ++i) {
    if (!want[i]) continue;
    out[i].point.y = marginal_.sampleContinuous(u[i].y, nullptr, &out[i].row);
    blockOf[i] = findBlock(out[i].row, clampUnit(u[i].x), within[i]);
    __builtin_prefetch(&block(out[i].row, blockOf[i]));
  }
  for (int i = 0; i < n; ++i)
    if (want[i]) finish(out[i].row, blockOf[i], within[i], out[i]);
}

}  // namespace glossy
