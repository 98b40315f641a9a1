// Correlated multi-jittered sampling (Kensler 2013, "Correlated Multi-Jittered Sampling", Pixar Technical
// Memo 13-01), padded per dimension: the kind of sampler Mitsuba 3 calls `multijitter`.
//
// In every pair of dimensions a pixel's N samples lie one per cell of an m × n grid, and one in each of the
// grid's m·n thin columns and m·n thin rows (counts with no such grid: CmjPattern); a 1D value is one point
// in each of N intervals. Unlike a (0,2)-sequence, whose prefixes are nets only at powers of two, this
// stratifies the count asked for: 90 samples are better than 64, not barely better (docs/rendering.md).
//
// Each dimension shuffles the sample index with its own permutation, which decorrelates the pairs; the
// permutations and the jitter are hashed from (seed, pass, pixel, dimension), so a value depends only on
// those and the sample index: renders are identical whatever the thread count or tile order. The pattern
// needs the count up front, so a progressive pass is a pattern of its own, seeded apart from the others.
#pragma once

#include "materials/core/types.h"

#include <array>
#include <bit>
#include <cstdint>
#include <memory>
#include <vector>

namespace glossy {

namespace cmj_detail {

inline uint64_t mix(uint32_t a, uint32_t b) {  // murmur3's finaliser on two words: all 64 bits mixed
  uint64_t h = (uint64_t(a) << 32 | b) * 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  h ^= h >> 33;
  return h;
}
inline uint32_t hash(uint32_t a, uint32_t b) { return static_cast<uint32_t>(mix(a, b)); }

// [0, size) and what permute needs of it, computed once per render: mask = 2^k − 1 for the smallest
// 2^k ≥ size (the domain of its bijection), and half of k rounded up.
struct PermutationRange {
  explicit PermutationRange(uint32_t n = 1)
      : size(n == 0 ? 1 : n), mask(size <= 1 ? 0u : std::bit_ceil(size) - 1u),
        halfWidth((std::bit_width(mask) + 1) / 2) {}
  uint32_t size, mask;
  int halfWidth;
};

// A seeded permutation of [0, size), from a 64-bit key.
// First a cheap bijection of the k-bit integers (xor or add the key's low half, multiply by an odd number,
// xor-shift by half the width: each invertible modulo 2^k), applied again until it lands in range (cycle
// walking, fewer than two rounds on average). It decorrelates, but a family this small is far from
// uniform over all permutations: for a fixed i its value is not uniform over keys (±15 % on [0, 10)), and
// samples placed by it would be biased. So the result is then rotated by an offset drawn uniformly from
// [0, size) with the key's other half: whatever the bijection, every i then goes to every value with the
// same probability, which is all an unbiased sampler needs.
// One round of the bijection, and the rotation after the walk (key's high half, `rotation`).
inline uint32_t permuteRound(uint32_t i, uint32_t mask, uint32_t half, uint32_t seed) {
  i ^= seed;
  i = (i * 0x9e3779b1u) & mask;
  i ^= i >> half;
  i += seed >> 10;
  i = (i * (((seed >> 20) << 1) | 1u)) & mask;
  i ^= i >> half;
  i ^= seed >> 21;
  i = (i * 0x85ebca6bu) & mask;
  i ^= i >> half;
  return i;
}
inline uint32_t permuteRotate(uint32_t i, uint32_t size, uint32_t rotation) {
  i += uint32_t(uint64_t(rotation) * size >> 32);
  return i >= size ? i - size : i;
}
inline uint32_t permute(uint32_t i, const PermutationRange& range, uint64_t key) {
  if (range.mask == 0) return 0;
  do {
    i = permuteRound(i, range.mask, uint32_t(range.halfWidth), uint32_t(key));
  } while (i >= range.size);
  return permuteRotate(i, range.size, uint32_t(key >> 32));
}

inline double toUnit(uint32_t x) { return x * 0x1p-32; }  // in [0, 1): never 1

// (k + j) / n with j < 1 can round up to the next stratum's edge, and past the last one to 1.
inline double belowOne(double x) { return x < 1.0 ? x : 0x1.fffffffffffffp-1; }

}  // namespace cmj_detail

// The layout of every pixel's pattern for N samples: N cells of area 1/N that tile the square, in m
// columns. Where N = m·n with m ≤ n ≤ 2m this is the m × n grid (90 = 9 × 10, 128 = 8 × 16). Any other N
// takes m = ⌊√N⌋ columns of two heights: the first r = N mod m hold ⌊N/m⌋ + 1 cells, the rest ⌊N/m⌋, and
// each column is as wide as its cell count / N (89 = 8 columns of 10 + 1 of 9). So no count leaves a cell
// empty: a padded grid (86 samples in 9 × 10 cells) must leave some out, and each cell left out cost
// stratification (rel. RMSE · √spp on the benchmark: 0.114 at 90 = 9 × 10, 0.125 at 86 in those cells).
// Thin columns are 1/N wide everywhere; thin rows split a column's cells among the columns of its height.
class CmjPattern {
 public:
  // splits > 1: the pattern also holds one of count · k points for each k ≤ splits, from which a sample
  // may take k draws of one dimension (CmjSampler::getSplits2D).
  explicit CmjPattern(uint32_t count, uint32_t splits = 1) : count_(count == 0 ? 1 : count) {
    splits_ = splits > 1 ? splits : 1;
    for (uint32_t k = 2; k <= splits_; ++k) splitBy_.push_back(std::make_shared<const CmjPattern>(count_ * k));
    uint32_t root = 1;
    while ((root + 1) * (root + 1) <= count_) ++root;
    // A full grid if there is one (N < 4 has only 1 × N), else ⌊√N⌋ columns.
    columns_ = root;
    for (uint32_t m = root; m > 0; --m) {
      const uint32_t n = count_ / m;
      if (n > 2 * m && root > 1) break;  // smaller m only stretch the grid further
      if (n * m == count_) {
        columns_ = m;
        break;
      }
    }
    rows_ = count_ / columns_;
    const uint32_t wide = count_ % columns_;
    bands_[0] = Band(0, rows_ + 1, wide);
    bands_[1] = Band(wide * (rows_ + 1), rows_, columns_ - wide);
    countRange_ = cmj_detail::PermutationRange(count_);
    perCount_ = 1.0 / count_;
  }

  uint32_t count() const { return count_; }
  uint32_t columns() const { return columns_; }          // m
  uint32_t rows() const { return rows_; }                // cells in each of the narrow columns, ⌊N/m⌋
  uint32_t wideColumns() const { return bands_[0].columns; }  // the first r columns hold rows() + 1 cells
  uint32_t splits() const { return splits_; }
  // The pattern of count() · splits() points; this one when splits() is 1.
  const CmjPattern& split() const { return split(splits_); }
  // The pattern of count() · k points, 1 ≤ k ≤ splits(); this one when k is 1.
  const CmjPattern& split(uint32_t k) const { return k <= 1 ? *this : *splitBy_[k - 2]; }

 private:
  friend class CmjSampler;
  // The columns of one height: they start at thin column `start` (and cell index `start`: a band's cells
  // are numbered row by row, as in Kensler's grid), each `height` cells tall and `height` thin columns wide.
  struct Band {
    Band() = default;
    Band(uint32_t first, uint32_t cells, uint32_t count)
        : start(first), height(cells), columns(count), heightRange(cells), columnRange(count),
          perThinRow(1.0 / (double(cells) * (count == 0 ? 1 : count))) {}
    uint32_t start = 0, height = 1, columns = 0;
    cmj_detail::PermutationRange heightRange, columnRange;
    double perThinRow = 1.0;  // 1 / (height · columns): a thin row's height
  };
  uint32_t count_, columns_ = 1, rows_ = 1, splits_ = 1;
  std::vector<std::shared_ptr<const CmjPattern>> splitBy_;  // [k − 2]: the pattern of count · k points
  Band bands_[2];  // the wide columns (possibly none), then the narrow ones
  cmj_detail::PermutationRange countRange_;
  double perCount_ = 1.0;  // 1 / N
};

// The seeds of one pixel's dimensions. A pixel's samples differ only in their index, so the samples traced
// together share one CmjPixel: the first to reach a dimension hashes its seeds, the others reuse them.
class CmjPixel {
 public:
  // Independent hashes, not multiples of one seed: a multiple's low bits are a function of the seed's
  // low bits, which is all a small permutation reads, and correlated permutations bias the points.
  struct Seeds {
    uint64_t cell, column, row;  // keys of the index shuffle and of the thin-column and thin-row permutations
  };

  // pass tells a progressive render's passes apart.
  CmjPixel(uint32_t seed, uint32_t pass, uint32_t x, uint32_t y)
      : pixelSeed_(cmj_detail::hash(cmj_detail::hash(x, y), cmj_detail::hash(seed, pass))) {}

  uint32_t seed() const { return pixelSeed_; }  // with the pattern, all that its values depend on
  Seeds seeds(uint32_t dimension) {
    if (dimension >= kCached) return compute(dimension);
    if (!(known_ >> dimension & 1u)) {
      cache_[dimension] = compute(dimension);
      known_ |= 1u << dimension;
    }
    return cache_[dimension];
  }

 private:
  static constexpr uint32_t kCached = 32;
  Seeds compute(uint32_t dimension) const {
    const uint64_t cell = cmj_detail::mix(pixelSeed_, dimension);
    const uint64_t column = cmj_detail::mix(uint32_t(cell), 0x9e3779b9u);
    const uint64_t row = cmj_detail::mix(uint32_t(column), 0x7f4a7c15u);
    return {cell, column, row};
  }

  uint32_t pixelSeed_;
  uint32_t known_ = 0;  // bit d: cache_[d] is filled
  std::array<Seeds, kCached> cache_{};  // zeroed only because GCC cannot see that known_ guards it
};

// One sample of a pixel: its 2D and 1D values, dimension after dimension.
class CmjSampler {
 public:
  CmjSampler() = default;
  // sampleIndex < pattern.count().
  CmjSampler(const CmjPattern& pattern, CmjPixel& pixel, uint32_t sampleIndex)
      : pattern_(&pattern), pixel_(&pixel), index_(sampleIndex) {}

  // The dimension's shuffle of the index picks cell i of column c; inside it the point's thin column is
  // a permutation of i and its thin row one of c, the same permutations in every column of a height (the
  // "correlated" offsets, which put one point in each thin column and row), plus jitter.
  Vec2 get2D() { return point2D(*pattern_, pixel_->seeds(dimension_++), index_); }
  // `count` split draws of the next dimension for this sample (count ≤ the pattern's splits()): points
  // index·count + j of the pixel's pattern of N·count points, so that the N samples' N·count draws are
  // stratified together, as a pattern of N·count samples would stratify them. A count of one is get2D()'s
  // (get1D()'s) value.
  void getSplits2D(uint32_t count, Vec2* out) {
    const CmjPixel::Seeds p = pixel_->seeds(dimension_++);
    for (uint32_t j = 0; j < count; ++j) out[j] = point2D(pattern_->split(count), p, index_ * count + j);
  }
  void getSplits1D(uint32_t count, double* out) {
    const CmjPixel::Seeds p = pixel_->seeds(dimension_++);
    for (uint32_t j = 0; j < count; ++j) out[j] = point1D(pattern_->split(count), p, index_ * count + j);
  }

  // The same draws for many samplers at once: out[lanes[k]] = samplers[lanes[k]].get2D() (get1D), for
  // k < n, the same values. The lanes' hashes and permutations are computed stage by stage for all of them
  // (cmj_sampler.cpp), so their long dependency chains overlap where one draw at a time waits on each
  // step. The samplers must share one pattern.
  static void get2D(CmjSampler* samplers, const int* lanes, int n, Vec2* out);
  static void get1D(CmjSampler* samplers, const int* lanes, int n, double* out);
  // Likewise samplers[lanes[k]].getSplits2D(counts[lanes[k]], out[lanes[k]]) (getSplits1D): a vertex's
  // several light or BSDF samples, all of them one batch.
  static void getSplits2D(CmjSampler* samplers, const int* lanes, int n, const uint32_t* counts, Vec2* const* out);
  static void getSplits1D(CmjSampler* samplers, const int* lanes, int n, const uint32_t* counts, double* const* out);

  // Passes over dimensions without computing them: a value depends on its dimension's index alone, so the
  // dimensions after them get what they would have had.
  void skip(uint32_t dimensions) { dimension_ += dimensions; }

  // All that the sampler's next values depend on: samplers with equal keys draw the same values.
  struct Key {
    const CmjPattern* pattern = nullptr;
    uint32_t pixelSeed = 0, index = 0, dimension = 0;
    bool operator==(const Key&) const = default;
  };
  Key key() const { return {pattern_, pixel_->seed(), index_, dimension_}; }

  // One point in each of the N intervals [k/N, (k+1)/N).
  double get1D() { return point1D(*pattern_, pixel_->seeds(dimension_++), index_); }

 private:
  // Point `index` of pattern g in the dimension whose seeds are p.
  static Vec2 point2D(const CmjPattern& g, const CmjPixel::Seeds& p, uint32_t index) {
    using namespace cmj_detail;
    const uint32_t cell = permute(index, g.countRange_, p.cell);
    const CmjPattern::Band& band = g.bands_[cell >= g.bands_[1].start];
    const uint32_t k = cell - band.start, i = k / band.columns, c = k - i * band.columns;
    const uint32_t thinColumn = permute(i, band.heightRange, p.column);
    const uint32_t thinRow = permute(c, band.columnRange, p.row);
    const uint64_t jitter = mix(cell, uint32_t(p.cell >> 32));
    // The column's first thin column + (thinColumn + j), over N; (i + (thinRow + j) / columns) / height.
    return {belowOne((band.start + c * band.height + thinColumn + toUnit(uint32_t(jitter >> 32))) * g.perCount_),
            belowOne((i * band.columns + thinRow + toUnit(uint32_t(jitter))) * band.perThinRow)};
  }
  static double point1D(const CmjPattern& g, const CmjPixel::Seeds& p, uint32_t index) {
    using namespace cmj_detail;
    const uint32_t k = permute(index, g.countRange_, p.cell);
    return belowOne((k + toUnit(hash(k, uint32_t(p.cell >> 32)))) * g.perCount_);
  }

  // The batch forms' stages (cmj_sampler.cpp): points index[k] of g in the dimensions of seeds[k], k < count
  // ≤ 128, into out[k], as point2D (point1D) gives them; the draws of one dimension for many samplers; their
  // split draws.
  static void points2D(const CmjPattern& g, const CmjPixel::Seeds* seeds, const uint32_t* index, int count, Vec2* out);
  static void points1D(const CmjPattern& g, const CmjPixel::Seeds* seeds, const uint32_t* index, int count, double* out);
  template <class T, class Points>
  static void draw(CmjSampler* samplers, const int* lanes, int n, T* out, Points points);
  template <class T, class Points>
  static void drawSplits(CmjSampler* samplers, const int* lanes, int n, const uint32_t* counts, T* const* out, Points points);

  const CmjPattern* pattern_ = nullptr;
  CmjPixel* pixel_ = nullptr;
  uint32_t index_ = 0;
  uint32_t dimension_ = 0;
};

}  // namespace glossy
