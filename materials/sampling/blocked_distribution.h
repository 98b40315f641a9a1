// A piecewise-constant density on [0,1)² laid out for random access to large tables: the environment
// light's importance sampling, where every lookup misses the cache.
//
// Like Distribution2D it inverts the CDFs, the marginal over rows and then the chosen row's conditional,
// so the map from u to the point is monotone in each coordinate and a stratified u stays stratified. Its
// conditionals are stored in two levels: each row's CDF over blocks of kBlock cells (double, small enough
// to stay cached: 264 bytes a row of 1024 cells), and each block's CDF over its cells in 16 bits, one
// cache line per block. A sample then reads one line that can miss, where a full CDF and its guide table
// read two or three in a chain (a guide entry, then the CDF lines it points to), and this table is a
// tenth of their size (1.2 MB against 10 MB for a 1024 × 512 map).
//
// Quantising a block's CDF changes the density a little (a cell's share of its block is a multiple of
// 1/65535; a cell with any weight keeps at least one), never its consistency: cellDensity is the density
// the sampler draws from, exactly, so estimators that divide by it stay unbiased. Zero-weight cells are
// never drawn and have density 0, zero rows likewise; an all-zero table is uniform.
#pragma once

#include "materials/core/types.h"
#include "materials/sampling/distribution.h"
#include "materials/sampling/huge_pages.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace glossy {

class BlockedDistribution2D {
 public:
  static constexpr std::size_t kBlock = 32;  // cells per block: 31 16-bit thresholds and a zero, 64 bytes

  // A plain aggregate, always built whole (batch callers keep arrays of them that are not zeroed).
  struct Sample {
    Vec2 point;               // in [0,1)²
    std::size_t column, row;  // the cell holding point
  };

  BlockedDistribution2D() = default;
  // values: width × height non-negative, finite weights, row-major (throws std::invalid_argument
  // otherwise, or if the size does not match).
  BlockedDistribution2D(std::span<const double> values, std::size_t width, std::size_t height);

  std::size_t width() const { return width_; }
  std::size_t height() const { return marginal_.size(); }

  // u in [0,1)² (clamped). The density at sample(u).point is cellDensity of its cell.
  Sample sample(Vec2 u) const;
  // out[i] = sample(u[i]) for the lanes with want[i], i < n ≤ kMaxBatch: the lanes' block lines are
  // fetched together, so that their cache misses overlap.
  static constexpr int kMaxBatch = 64;
  void sample(const bool* want, const Vec2* u, Sample* out, int n) const;

  // The density the sampler draws from, on cell (column, row), with respect to area on the unit square.
  double cellDensity(std::size_t column, std::size_t row) const;
  double pdf(Vec2 point) const;  // cellDensity of the cell holding point; 0 outside [0,1]²

 private:
  static constexpr uint32_t kScale = 65535;  // a block's cells' shares are multiples of 1/kScale
  struct alignas(64) Block {
    uint16_t start[kBlock];  // cell k's share begins at start[k] / kScale; start[0] = 0
  };
  static_assert(sizeof(Block) == 64, "a block is one cache line");

  // Where u (in [0,1)) falls in row `row`: its block, and u's position within the block's mass in
  // [0, kScale).
  std::size_t findBlock(std::size_t row, double u, double& within) const;
  const Block& block(std::size_t row, std::size_t b) const { return blocks_[row * blocksPerRow_ + b]; }
  // The column and the x of the sample, given its block and its position within the block's mass.
  void finish(std::size_t row, std::size_t b, double within, Sample& s) const;

  std::size_t width_ = 0, blocksPerRow_ = 0, cdfStride_ = 0;
  Distribution1D marginal_;            // over rows, weighted by each row's sum
  std::vector<double> blockCdf_;       // row y's CDF over its blocks at [y·cdfStride_, (y + 1)·cdfStride_)
  HugePageVector<Block> blocks_;       // row y's blocks at [y·blocks, (y + 1)·blocks)
};

}  // namespace glossy
