// CmjSampler's batch draws: get2D, get1D and their split forms for many lanes, stage by stage over arrays of lanes, with the
// same arithmetic as the one-lane forms in cmj_sampler.h (so the same values, bit for bit).
#include "renderer/samplers/cmj_sampler.h"

#include <algorithm>

namespace glossy {

namespace {

constexpr int kChunk = 128;  // lanes per pass, on the stack

// Each lane's permutation range, as arrays (the form the vectorised rounds read).
struct RangeLanes {
  uint32_t size[kChunk], mask[kChunk], half[kChunk];
  void set(int k, const cmj_detail::PermutationRange& range) {
    size[k] = range.size;
    mask[k] = range.mask;
    half[k] = uint32_t(range.halfWidth);
  }
};

// permute() for n lanes, each with its own range (size, mask, half width) and key (its low half seeds the
// bijection, its high half the rotation). The cycle walking becomes rounds over every lane until none is
// out of range; a lane in range keeps its value, so each lane takes exactly the rounds permute() takes.
// Plain loops over arrays of 32-bit lanes, which the compiler vectorises: an AVX2 clone (8 lanes an
// instruction, with per-lane shifts) is chosen at run time where the CPU has it, the baseline elsewhere.
// Integer arithmetic, so every clone gives the same values.
#if defined(__x86_64__)
__attribute__((target_clones("avx2", "default")))
#endif
void permuteLanes(const uint32_t* in, const RangeLanes& range, const uint32_t* seed, const uint32_t* rotation,
                  uint32_t* out, int n) {
  using namespace cmj_detail;
  const uint32_t *size = range.size, *mask = range.mask, *half = range.half;
  uint32_t outside = 0;
  for (int k = 0; k < n; ++k) {
    out[k] = permuteRound(in[k], mask[k], half[k], seed[k]);
    outside |= out[k] >= size[k];
  }
  while (outside) {
    outside = 0;
    for (int k = 0; k < n; ++k) {
      const uint32_t next = permuteRound(out[k], mask[k], half[k], seed[k]);
      out[k] = out[k] >= size[k] ? next : out[k];
      outside |= out[k] >= size[k];
    }
  }
  // A range of one has mask 0, and every round gives 0: permute()'s early return.
  for (int k = 0; k < n; ++k) out[k] = permuteRotate(out[k], size[k], rotation[k]);
}

}  // namespace

void CmjSampler::points2D(const CmjPattern& g, const CmjPixel::Seeds* seeds, const uint32_t* index, int count, Vec2* out) {
  using namespace cmj_detail;
  uint32_t cell[kChunk], i[kChunk], c[kChunk];
  uint32_t thinColumn[kChunk], thinRow[kChunk];
  int band[kChunk];
  // Zeroed only because GCC cannot see that count ≤ kChunk fills what permuteLanes reads.
  RangeLanes range{};
  // The three keys' halves: key[0][k] low, key[1][k] high for the cell; then the column's, the row's.
  uint32_t key[6][kChunk]{};
  for (int k = 0; k < count; ++k) {
    const CmjPixel::Seeds& p = seeds[k];
    key[0][k] = uint32_t(p.cell);
    key[1][k] = uint32_t(p.cell >> 32);
    key[2][k] = uint32_t(p.column);
    key[3][k] = uint32_t(p.column >> 32);
    key[4][k] = uint32_t(p.row);
    key[5][k] = uint32_t(p.row >> 32);
    range.set(k, g.countRange_);
  }
  permuteLanes(index, range, key[0], key[1], cell, count);
  // The cell's column of its band, and its place in it; then the thin column (a permutation of i over
  // the band's height) and the thin row (of c over its columns).
  for (int k = 0; k < count; ++k) {
    band[k] = cell[k] >= g.bands_[1].start;
    const CmjPattern::Band& b = g.bands_[band[k]];
    const uint32_t j = cell[k] - b.start;
    i[k] = j / b.columns;
    c[k] = j - i[k] * b.columns;
    range.set(k, b.heightRange);
  }
  permuteLanes(i, range, key[2], key[3], thinColumn, count);
  for (int k = 0; k < count; ++k) range.set(k, g.bands_[band[k]].columnRange);
  permuteLanes(c, range, key[4], key[5], thinRow, count);
  for (int k = 0; k < count; ++k) {
    const CmjPattern::Band& b = g.bands_[band[k]];
    const uint64_t jitter = mix(cell[k], key[1][k]);
    out[k] = {belowOne((b.start + c[k] * b.height + thinColumn[k] + toUnit(uint32_t(jitter >> 32))) * g.perCount_),
              belowOne((i[k] * b.columns + thinRow[k] + toUnit(uint32_t(jitter))) * b.perThinRow)};
  }
}

void CmjSampler::points1D(const CmjPattern& g, const CmjPixel::Seeds* seeds, const uint32_t* index, int count, double* out) {
  using namespace cmj_detail;
  uint32_t interval[kChunk], low[kChunk]{}, high[kChunk]{};
  RangeLanes range{};
  for (int k = 0; k < count; ++k) {
    low[k] = uint32_t(seeds[k].cell);
    high[k] = uint32_t(seeds[k].cell >> 32);
    range.set(k, g.countRange_);
  }
  permuteLanes(index, range, low, high, interval, count);
  for (int k = 0; k < count; ++k) out[k] = belowOne((interval[k] + toUnit(hash(interval[k], high[k]))) * g.perCount_);
}

template <class T, class Points>
void CmjSampler::draw(CmjSampler* samplers, const int* lanes, int n, T* out, Points points) {
  for (int first = 0; first < n; first += kChunk) {
    const int count = std::min(kChunk, n - first);
    const int* lane = lanes + first;
    CmjPixel::Seeds seeds[kChunk];
    uint32_t index[kChunk];
    T values[kChunk];
    for (int k = 0; k < count; ++k) {
      CmjSampler& s = samplers[lane[k]];
      seeds[k] = s.pixel_->seeds(s.dimension_++);
      index[k] = s.index_;
    }
    points(*samplers[lane[0]].pattern_, seeds, index, count, values);
    for (int k = 0; k < count; ++k) out[lane[k]] = values[k];
  }
}

template <class T, class Points>
void CmjSampler::drawSplits(CmjSampler* samplers, const int* lanes, int n, const uint32_t* counts, T* const* out, Points points) {
  for (int first = 0; first < n; first += kChunk) {
    const int chunk = std::min(kChunk, n - first);
    const int* lane = lanes + first;
    CmjPixel::Seeds seeds[kChunk];
    uint32_t most = 0;
    for (int k = 0; k < chunk; ++k) {
      CmjSampler& s = samplers[lane[k]];
      seeds[k] = s.pixel_->seeds(s.dimension_++);
      most = std::max(most, counts[lane[k]]);
    }
    // Count by count (each its own pattern): the draws of every lane that takes it, kChunk at a time.
    for (uint32_t size = 1; size <= most; ++size) {
      const CmjPattern& g = samplers[lane[0]].pattern_->split(size);
      CmjPixel::Seeds drawSeeds[kChunk];
      uint32_t index[kChunk];
      T values[kChunk], *target[kChunk];
      int m = 0;
      const auto flush = [&] {
        points(g, drawSeeds, index, m, values);
        for (int e = 0; e < m; ++e) *target[e] = values[e];
        m = 0;
      };
      for (int k = 0; k < chunk; ++k) {
        if (counts[lane[k]] != size) continue;
        for (uint32_t j = 0; j < size; ++j) {
          drawSeeds[m] = seeds[k];
          index[m] = samplers[lane[k]].index_ * size + j;
          target[m] = out[lane[k]] + j;
          if (++m == kChunk) flush();
        }
      }
      if (m > 0) flush();
    }
  }
}

void CmjSampler::get2D(CmjSampler* samplers, const int* lanes, int n, Vec2* out) { draw(samplers, lanes, n, out, points2D); }
void CmjSampler::get1D(CmjSampler* samplers, const int* lanes, int n, double* out) { draw(samplers, lanes, n, out, points1D); }
void CmjSampler::getSplits2D(CmjSampler* samplers, const int* lanes, int n, const uint32_t* counts, Vec2* const* out) {
  drawSplits(samplers, lanes, n, counts, out, points2D);
}
void CmjSampler::getSplits1D(CmjSampler* samplers, const int* lanes, int n, const uint32_t* counts, double* const* out) {
  drawSplits(samplers, lanes, n, counts, out, points1D);
}

}  // namespace glossy
