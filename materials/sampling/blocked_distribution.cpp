// BlockedDistribution2D: building the rows' trees of 16-bit CDFs, and descending them.
#include "materials/sampling/blocked_distribution.h"

#include "materials/sampling/unit_interval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glossy {

BlockedDistribution2D::BlockedDistribution2D(std::span<const double> values, std::size_t width, std::size_t height)
    : BlockedDistribution2D(width, height, [&](std::size_t y, std::span<double> out) {
        if (values.size() != width * height)
          throw std::invalid_argument("BlockedDistribution2D: table size does not match width × height");
        std::copy_n(values.begin() + std::ptrdiff_t(y * width), width, out.begin());
      }) {}

BlockedDistribution2D::BlockedDistribution2D(std::size_t width, std::size_t height, const RowValues& rowValues)
    : width_(width) {
  if (width == 0 || height == 0)
    throw std::invalid_argument("BlockedDistribution2D: table size does not match width × height");

  // Blocks per level, bottom (over cells) first, up to a single top block.
  std::vector<std::size_t> counts{(width + kBlock - 1) / kBlock};
  while (counts.back() > 1) counts.push_back((counts.back() + kBlock - 1) / kBlock);
  std::reverse(counts.begin(), counts.end());
  for (std::size_t c : counts) {
    levelStart_.push_back(blocksPerRow_);
    blocksPerRow_ += c;
  }
  blocks_.resize(height * blocksPerRow_);

  std::vector<double> rowSums(height), row(width), mass, parentMass;
  for (std::size_t y = 0; y < height; ++y) {
    rowValues(y, row);
    for (double v : row)
      if (!(v >= 0.0) || !std::isfinite(v))
        throw std::invalid_argument("BlockedDistribution2D: negative or non-finite value");
    double sum = 0.0;
    for (std::size_t x = 0; x < width; ++x) sum += row[x];
    rowSums[y] = sum;
    // A row with no weight is drawn only from an all-zero table, which is uniform: its cells weigh alike.
    mass.assign(row.begin(), row.end());
    if (!(sum > 0.0)) std::fill(mass.begin(), mass.end(), 1.0);

    for (std::size_t level = counts.size(); level-- > 0;) {
      parentMass.assign(counts[level], 0.0);
      for (std::size_t b = 0; b < counts[level]; ++b) {
        const std::size_t first = b * kBlock, children = std::min(kBlock, mass.size() - first);
        double blockMass = 0.0;
        std::size_t withWeight = 0;
        for (std::size_t k = 0; k < children; ++k) {
          blockMass += mass[first + k];
          withWeight += mass[first + k] > 0.0 ? 1 : 0;
        }
        parentMass[b] = blockMass;
        // Every child with weight gets one 1/kScale share, the rest are shared out in proportion to the
        // masses (by rounding the running sum, so they add up exactly). A block without mass is never
        // reached; its shares are anything valid.
        uint16_t* start = blocks_[y * blocksPerRow_ + levelStart_[level] + b].start;
        const double spare = double(kScale - withWeight);
        double running = 0.0;
        std::size_t before = 0;
        for (std::size_t k = 0; k < kBlock; ++k) {
          if (k >= children) {
            start[k] = uint16_t(kScale);  // past the row's end: no share
            continue;
          }
          start[k] = blockMass > 0.0 ? uint16_t(before + std::llround(spare * (running / blockMass)))
                                     : uint16_t(k * kScale / children);
          running += mass[first + k];
          before += mass[first + k] > 0.0 ? 1 : 0;
        }
      }
      mass.swap(parentMass);
    }
  }
  marginal_ = Distribution1D(rowSums);
}

double BlockedDistribution2D::cellDensity(std::size_t column, std::size_t row) const {
  double density = marginal_.pdf((double(row) + 0.5) / double(height())) * double(width_);
  const std::size_t levels = levelStart_.size();
  static_assert(kBlock == 32, "a level is 5 bits of the column");
  std::size_t shift = 5 * levels;
  for (std::size_t level = 0; level < levels; ++level) {
    shift -= 5;
    const std::size_t index = column >> shift, b = index / kBlock, k = index % kBlock;
    const uint16_t* start = block(row, level, b).start;
    const uint32_t upper = k + 1 < kBlock ? start[k + 1] : kScale;
    density *= double(upper - start[k]) / kScale;
  }
  return density;
}

double BlockedDistribution2D::pdf(Vec2 point) const {
  if (!(point.x >= 0.0 && point.x <= 1.0 && point.y >= 0.0 && point.y <= 1.0)) return 0.0;
  const std::size_t row = std::min(std::size_t(point.y * double(height())), height() - 1);
  const std::size_t column = std::min(std::size_t(point.x * double(width_)), width_ - 1);
  return cellDensity(column, row);
}

BlockedDistribution2D::Sample BlockedDistribution2D::sample(Vec2 u) const {
  const bool want = true;
  Sample s;
  sample(&want, &u, &s, 1);
  return s;
}

void BlockedDistribution2D::sample(const bool* want, const Vec2* u, Sample* out, int n) const {
  std::size_t index[kMaxBatch];
  double within[kMaxBatch];
  for (int i = 0; i < n; ++i) {
    if (!want[i]) continue;
    out[i].point.y = marginal_.sampleContinuous(u[i].y, nullptr, &out[i].row);
    within[i] = std::min(clampUnit(u[i].x) * kScale, kBelowScale);
    index[i] = 0;
  }
  // Level by level for all lanes: the blocks of the next level are fetched while this one is read.
  const std::size_t levels = levelStart_.size();
  for (std::size_t level = 0; level < levels; ++level) {
    const bool bottom = level + 1 == levels;
    for (int i = 0; i < n; ++i) {
      if (!want[i]) continue;
      index[i] = index[i] * kBlock + descend(block(out[i].row, level, index[i]), within[i], bottom);
      if (!bottom) __builtin_prefetch(&block(out[i].row, level + 1, index[i]));
    }
  }
  // At the bottom, index is the column and within the point's place in its cell.
  for (int i = 0; i < n; ++i) {
    if (!want[i]) continue;
    out[i].column = index[i];
    out[i].point.x = pointInBin(index[i], within[i], width_);
  }
}

}  // namespace glossy
