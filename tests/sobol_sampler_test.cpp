// The Owen-scrambled Sobol' sampler: values in [0,1), determinism, and the stratification that makes it
// worth having — every power-of-two prefix of a pixel's samples is a (0,2)-net in each dimension pair.
#include "renderer/sampling/sobol_sampler.h"
#include "tests/support/test_support.h"

#include <set>

namespace glossy::test {

namespace {

// The sampler's definition written out the slow, obvious way: Owen scramble = reverse, Laine-Karras,
// reverse; dimension 1 = the generator matrix applied bit by bit.
Vec2 definitionGet2D(uint32_t seed, uint32_t x, uint32_t y, uint32_t index, uint32_t dimension) {
  using namespace sobol_detail;
  auto reverse = [](uint32_t v) {
    uint32_t r = 0;
    for (int k = 0; k < 32; ++k) r |= ((v >> k) & 1u) << (31 - k);
    return r;
  };
  auto owen = [&](uint32_t v, uint32_t s) { return reverse(laineKarras(reverse(v), s)); };
  const uint32_t s = hash(hash(hash(x, y), seed), dimension);
  const uint32_t i = owen(index, hash(s, 0x9e3779b9u));
  uint32_t b = 0;
  for (int k = 0; k < 32; ++k)
    if (i >> k & 1u) b ^= kDim1[size_t(k)];
  return {toUnit(owen(reverse(i), hash(s, 1))), toUnit(owen(b, hash(s, 2)))};
}

}  // namespace

TEST(SobolSampler, FastPathEqualsTheDefinitionBitForBit) {
  for (uint32_t seed : {0u, 7u, 0xdeadbeefu})
    for (uint32_t pixel = 0; pixel < 20; ++pixel) {
      const uint32_t x = pixel * 37u, y = pixel * 11u + 3u;
      SobolPixel p(seed, x, y);
      for (uint32_t index : {0u, 1u, 2u, 5u, 63u, 64u, 1000u, 123456u, 0xFFFFFFFFu}) {
        SobolSampler s(p, index);
        for (uint32_t dim = 0; dim < 40; ++dim) {  // beyond the 32 dimensions whose seeds are cached
          const Vec2 expected = definitionGet2D(seed, x, y, index, dim);
          if (dim % 3 == 2) {
            ASSERT_EQ(s.get1D(), expected.x) << "seed " << seed << " index " << index << " dim " << dim;
          } else {
            ASSERT_EQ(s.get2D(), expected) << "seed " << seed << " index " << index << " dim " << dim;
          }
        }
      }
    }
}

TEST(SobolSampler, EveryPowerOfTwoPrefixIsAZeroTwoNet) {
  SobolPixel p(42, 3, 7);
  for (uint32_t log2n : {2u, 4u, 6u, 8u}) {
    const uint32_t n = 1u << log2n;
    for (uint32_t dim = 0; dim < 4; ++dim) {
      // For every split of n into 2^a × 2^b elementary boxes, each box holds exactly one point.
      for (uint32_t a = 0; a <= log2n; ++a) {
        const uint32_t cols = 1u << a, rows = n / cols;
        std::set<uint32_t> boxes;
        for (uint32_t i = 0; i < n; ++i) {
          SobolSampler s(p, i);
          Vec2 u;
          for (uint32_t d = 0; d <= dim; ++d) u = s.get2D();
          boxes.insert(uint32_t(u.x * cols) * rows + uint32_t(u.y * rows));
        }
        EXPECT_EQ(boxes.size(), n) << "n=" << n << " dim=" << dim << " boxes " << cols << "x" << rows;
      }
    }
  }
}

TEST(SobolSampler, DeterministicAndDecorrelatedAcrossPixelsAndDimensions) {
  SobolPixel pa(1, 10, 20), pb(1, 10, 20), pc(2, 10, 20), pd(1, 11, 20);
  SobolSampler a(pa, 5), b(pb, 5), c(pc, 5), d(pd, 5), a2(pa, 5);
  const Vec2 a0 = a.get2D(), a1 = a.get2D();
  EXPECT_EQ(a0, b.get2D());
  EXPECT_EQ(a1, b.get2D());
  EXPECT_EQ(a0, a2.get2D()) << "a second sample of the same pixel and index reuses the seeds to the same values";
  EXPECT_NE(a0, c.get2D()) << "the seed changes the points";
  EXPECT_NE(a0, a1) << "dimension pairs are scrambled independently";
  EXPECT_NE(a0, d.get2D()) << "neighbouring pixels are decorrelated";
}

TEST(SobolSampler, ValuesStayInTheHalfOpenUnitSquareAndAverageToAHalf) {
  SobolPixel p(9, 0, 0);
  double sum = 0.0;
  const int n = 1 << 14;
  for (int i = 0; i < n; ++i) {
    SobolSampler s(p, uint32_t(i));
    const Vec2 u = s.get2D();
    ASSERT_GE(u.x, 0.0);
    ASSERT_LT(u.x, 1.0);
    ASSERT_GE(u.y, 0.0);
    ASSERT_LT(u.y, 1.0);
    sum += u.x + u.y;
  }
  EXPECT_NEAR(sum / (2 * n), 0.5, 1e-3);
}

}  // namespace glossy::test
