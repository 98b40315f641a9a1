// Owen-scrambled Sobol' points, padded per dimension pair (Burley 2020, "Practical Hash-based Owen
// Scrambling"; the same construction as pbrt-v4's PaddedSobolSampler).
//
// Every 2D request takes the first two Sobol' dimensions at a sample index that is itself Owen-scrambled,
// with seeds hashed from (pixel, dimension, seed). So any power-of-two prefix of a pixel's samples is a
// stratified (0,2)-net in every pair of dimensions, the pairs are decorrelated from each other and from
// neighbouring pixels, and a value depends only on (seed, pixel, sample index, dimension): renders are
// identical whatever the thread count or tile order.
#pragma once

#include "materials/core/types.h"

#include <array>
#include <cstdint>

namespace glossy {

namespace sobol_detail {

constexpr uint32_t reverseBits(uint32_t x) {
  x = __builtin_bswap32(x);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

// Burley's improved Laine-Karras permutation: each bit is flipped depending only on the bits below it.
// Applied between two bit reversals it is a nested uniform (Owen) scramble, where each bit depends only on
// the bits above it.
constexpr uint32_t laineKarras(uint32_t x, uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// Generator matrix columns of the second Sobol' dimension (primitive polynomial x + 1): v_k = v_{k−1} ^ (v_{k−1} >> 1).
constexpr std::array<uint32_t, 32> makeSecondDimension() {
  std::array<uint32_t, 32> v{};
  v[0] = 0x80000000u;
  for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
  return v;
}
inline constexpr std::array<uint32_t, 32> kDim1 = makeSecondDimension();

// The second dimension is linear in the index's bits, and the Owen scramble wants it bit-reversed: so
// reverse(Σ_k bit_k(i)·v_k) is tabulated a byte of i at a time (4 KB, L1-resident), replacing a loop
// over all 32 bits of the scrambled index.
constexpr std::array<std::array<uint32_t, 256>, 4> makeReversedSecondDimensionTables() {
  std::array<std::array<uint32_t, 256>, 4> t{};
  for (int byte = 0; byte < 4; ++byte)
    for (uint32_t b = 0; b < 256; ++b) {
      uint32_t sum = 0;
      for (int k = 0; k < 8; ++k)
        if (b >> k & 1u) sum ^= kDim1[size_t(8 * byte + k)];
      t[size_t(byte)][b] = reverseBits(sum);
    }
  return t;
}
inline constexpr std::array<std::array<uint32_t, 256>, 4> kReversedDim1 = makeReversedSecondDimensionTables();

inline uint32_t reversedSecondDimension(uint32_t i) {
  return kReversedDim1[0][i & 0xFFu] ^ kReversedDim1[1][(i >> 8) & 0xFFu] ^ kReversedDim1[2][(i >> 16) & 0xFFu] ^
         kReversedDim1[3][i >> 24];
}

inline uint32_t hash(uint32_t a, uint32_t b) {  // murmur3-style mix of two words
  uint64_t h = (uint64_t(a) << 32 | b) * 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  h ^= h >> 33;
  return static_cast<uint32_t>(h);
}

inline double toUnit(uint32_t x) { return x * 0x1p-32; }  // in [0, 1): never 1

}  // namespace sobol_detail

// The scramble seeds of one pixel's dimensions. A pixel's samples differ only in their index, so the
// samples traced together share one SobolPixel: the first to reach a dimension hashes its seeds, the
// others reuse them.
class SobolPixel {
 public:
  struct Seeds {
    uint32_t index, x, y;  // of the index shuffle and of the two coordinates' scrambles
  };

  SobolPixel(uint32_t seed, uint32_t x, uint32_t y) : pixelSeed_(sobol_detail::hash(sobol_detail::hash(x, y), seed)) {}

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
    using sobol_detail::hash;
    const uint32_t s = hash(pixelSeed_, dimension);
    return {hash(s, 0x9e3779b9u), hash(s, 1), hash(s, 2)};
  }

  uint32_t pixelSeed_;
  uint32_t known_ = 0;  // bit d: cache_[d] is filled
  std::array<Seeds, kCached> cache_;
};

// One sample of a pixel: its 2D and 1D values, dimension after dimension.
class SobolSampler {
 public:
  SobolSampler() = default;
  SobolSampler(SobolPixel& pixel, uint32_t sampleIndex)
      : pixel_(&pixel), reversedIndex_(sobol_detail::reverseBits(sampleIndex)) {}

  // With R = bit reversal and LK the Laine-Karras step, the Owen scramble of x is R(LK(R(x))); the shuffled
  // index is i = R(LK(R(index))), Sobol' dimension 0 of i is R(i) and dimension 1 is P·i (P: kDim1). Written
  // out, R∘R cancels twice, and R(P·i) comes from the tables: four reversals instead of seven, no bit loop.
  Vec2 get2D() {
    using namespace sobol_detail;
    const SobolPixel::Seeds seeds = pixel_->seeds(dimension_++);
    const uint32_t i = reverseBits(laineKarras(reversedIndex_, seeds.index));
    return {toUnit(reverseBits(laineKarras(i, seeds.x))),
            toUnit(reverseBits(laineKarras(reversedSecondDimension(i), seeds.y)))};
  }

  // Exactly get2D().x, without computing the second coordinate.
  double get1D() {
    using namespace sobol_detail;
    const SobolPixel::Seeds seeds = pixel_->seeds(dimension_++);
    const uint32_t i = reverseBits(laineKarras(reversedIndex_, seeds.index));
    return toUnit(reverseBits(laineKarras(i, seeds.x)));
  }

 private:
  SobolPixel* pixel_ = nullptr;
  uint32_t reversedIndex_ = 0;
  uint32_t dimension_ = 0;
};

}  // namespace glossy
