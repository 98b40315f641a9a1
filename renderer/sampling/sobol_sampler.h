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

// Generator matrix columns of the second Sobol' dimension (primitive polynomial x + 1): v_k = v_{k−1} ^ (v_{k−1} >> 1).
constexpr std::array<uint32_t, 32> makeSecondDimension() {
  std::array<uint32_t, 32> v{};
  v[0] = 0x80000000u;
  for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
  return v;
}
inline constexpr std::array<uint32_t, 32> kDim1 = makeSecondDimension();

inline uint32_t reverseBits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

// Burley's improved Laine-Karras permutation; applied to bit-reversed input it is a nested uniform
// (Owen) scramble: each bit is flipped depending only on the bits above it.
inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
  x = reverseBits(x);
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return reverseBits(x);
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

class SobolSampler {
 public:
  explicit SobolSampler(uint32_t seed) : seed_(seed) {}

  void startPixelSample(uint32_t x, uint32_t y, uint32_t sampleIndex) {
    pixelSeed_ = sobol_detail::hash(sobol_detail::hash(x, y), seed_);
    index_ = sampleIndex;
    dimension_ = 0;
  }

  Vec2 get2D() {
    using namespace sobol_detail;
    const uint32_t s = hash(pixelSeed_, dimension_++);
    const uint32_t i = owenScramble(index_, hash(s, 0x9e3779b9u));
    uint32_t a = reverseBits(i), b = 0;  // dimension 0 is the van der Corput sequence
    for (uint32_t bits = i, k = 0; bits; bits >>= 1, ++k)
      if (bits & 1u) b ^= kDim1[k];
    return {toUnit(owenScramble(a, hash(s, 1))), toUnit(owenScramble(b, hash(s, 2)))};
  }

  // Exactly get2D().x, without computing the second coordinate.
  double get1D() {
    using namespace sobol_detail;
    const uint32_t s = hash(pixelSeed_, dimension_++);
    const uint32_t i = owenScramble(index_, hash(s, 0x9e3779b9u));
    return toUnit(owenScramble(reverseBits(i), hash(s, 1)));
  }

 private:
  uint32_t seed_;
  uint32_t pixelSeed_ = 0;
  uint32_t index_ = 0;
  uint32_t dimension_ = 0;
};

}  // namespace glossy
