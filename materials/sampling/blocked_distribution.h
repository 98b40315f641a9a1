// A piecewise-constant density on [0,1)² laid out for random access to large tables: the environment
// light's importance sampling, where lookups miss the cache.
//
// Like Distribution2D it inverts the CDFs, the marginal over rows and then the chosen row's conditional,
// so the map from u to the point is monotone in each coordinate and a stratified u stays stratified. Its
// conditionals are stored as trees of blocks: a block is one cache line, the 16-bit CDF of 32 children
// (cells, or blocks of the level below), and a row of W cells is a tree ⌈log₃₂ W⌉ blocks deep (2 for
// 1024 columns, 3 for 2048 to 32 768). A sample reads one block per level, the top ones small enough to
// stay cached, where a full CDF and its guide table read two or three lines in a chain that all miss; and
// the table is a tenth of their size (1.1 MB against 10.5 MB for a 1024 × 512 map, 17 against 168 for
// 4096 × 2048).
//
// Quantising the CDFs changes the density a little (a child's share of its block is a multiple of
// 1/65535, and a child with any weight keeps at least one), never its consistency: cellDensity is the
// density the sampler draws from, exactly, so estimators that divide by it stay unbiased. Zero-weight
// cells are never drawn and have density 0, zero rows likewise; an all-zero table is uniform.
#pragma once

#include "materials/core/types.h"
#include "materials/sampling/distribution.h"
#include "materials/sampling/unit_interval.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace glossy {

class BlockedDistribution2D {
 public:
  static constexpr std::size_t kBlock = 32;  // children per block: a zero and 31 16-bit thresholds, 64 bytes

  // A plain aggregate, always built whole (batch callers keep arrays of them that are not zeroed).
  struct Sample {
    Vec2 point;               // in [0,1)²
    std::size_t column, row;  // the cell holding point
  };

  BlockedDistribution2D() = default;
  // values: width × height non-negative, finite weights, row-major (throws std::invalid_argument
  // otherwise, or if the size does not match).
  BlockedDistribution2D(std::span<const double> values, std::size_t width, std::size_t height);
  // The same, with each row's weights written by rowValues(row, out) (out: width long), called once per
  // row in order: a large table need never exist whole (the environment light of a 16k map).
  using RowValues = std::function<void(std::size_t row, std::span<double> out)>;
  BlockedDistribution2D(std::size_t width, std::size_t height, const RowValues& rowValues);

  std::size_t width() const { return width_; }
  std::size_t height() const { return marginal_.size(); }

  // u in [0,1)² (clamped). The density at sample(u).point is cellDensity of its cell.
  Sample sample(Vec2 u) const;
  // out[i] = sample(u[i]) for the lanes with want[i], i < n ≤ kMaxBatch: each level's blocks are
  // fetched for all lanes before the next level is read, so that the lanes' cache misses overlap.
  static constexpr int kMaxBatch = 128;
  void sample(const bool* want, const Vec2* u, Sample* out, int n) const;

  // The density the sampler draws from, on cell (column, row), with respect to area on the unit square.
  double cellDensity(std::size_t column, std::size_t row) const;
  double pdf(Vec2 point) const;  // cellDensity of the cell holding point; 0 outside [0,1]²

 private:
  static constexpr uint32_t kScale = 65535;  // a block's children's shares are multiples of 1/kScale
  struct alignas(64) Block {
    uint16_t start[kBlock];  // child k's share begins at start[k] / kScale; start[0] = 0
  };
  static_assert(sizeof(Block) == 64, "a block is one cache line");

  const Block& block(std::size_t row, std::size_t level, std::size_t index) const {
    return blocks_[row * blocksPerRow_ + levelStart_[level] + index];
  }
  // One level down: the child of `block` that `within` (a position in the block's mass, in [0, kScale))
  // falls in, and within's position in that child's mass (or, at the bottom, in the cell, in [0, 1)).
  // Inline (it runs per lane and level) and free of libm calls: kBelowScale is nextafter(kScale, 0).
  static constexpr double kBelowScale = double(kScale) - 0x1p-37;
  static std::size_t descend(const Block& block, double& within, bool bottom) {
    const uint16_t* start = block.start;
    // The last k with start[k] ≤ within (start[0] = 0), by halving 32 without branches: its share then
    // reaches past within, so a child without a share is never the answer. The thresholds are integers, so
    // comparing them with ⌊within⌋ is the same test, without a conversion to double in each step's chain.
    const uint32_t floorWithin = uint32_t(within);
    std::size_t k = 0;
    for (std::size_t step = kBlock / 2; step > 0; step /= 2) k += start[k + step] <= floorWithin ? step : 0;
    const double lower = start[k], upper = k + 1 < kBlock ? start[k + 1] : kScale;
    const double fraction = (within - lower) / (upper - lower);
    within = bottom ? std::clamp(fraction, 0.0, kOneMinusEpsilon) : std::clamp(fraction * kScale, 0.0, kBelowScale);
    return k;
  }

  std::size_t width_ = 0, blocksPerRow_ = 0;
  std::vector<std::size_t> levelStart_;  // per level, top first: its first block in a row's blocks
  Distribution1D marginal_;              // over rows, weighted by each row's sum
  std::vector<Block> blocks_;         // row y's tree at [y·blocksPerRow_, (y + 1)·blocksPerRow_)
};

}  // namespace glossy
