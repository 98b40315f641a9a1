// The Owen-scrambled Sobol' sampler: values in [0,1), determinism, and the stratification that makes it
// worth having — every power-of-two prefix of a pixel's samples is a (0,2)-net in each dimension pair.
#include "renderer/sampling/sobol_sampler.h"
#include "tests/support/test_support.h"

#include <set>

namespace glossy::test {

TEST(SobolSampler, EveryPowerOfTwoPrefixIsAZeroTwoNet) {
  SobolSampler s(42);
  for (uint32_t log2n : {2u, 4u, 6u, 8u}) {
    const uint32_t n = 1u << log2n;
    for (uint32_t dim = 0; dim < 4; ++dim) {
      // For every split of n into 2^a × 2^b elementary boxes, each box holds exactly one point.
      for (uint32_t a = 0; a <= log2n; ++a) {
        const uint32_t cols = 1u << a, rows = n / cols;
        std::set<uint32_t> boxes;
        for (uint32_t i = 0; i < n; ++i) {
          s.startPixelSample(3, 7, i);
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
  SobolSampler a(1), b(1), c(2);
  a.startPixelSample(10, 20, 5);
  b.startPixelSample(10, 20, 5);
  c.startPixelSample(10, 20, 5);
  const Vec2 a0 = a.get2D(), a1 = a.get2D();
  EXPECT_EQ(a0, b.get2D());
  EXPECT_EQ(a1, b.get2D());
  EXPECT_NE(a0, c.get2D()) << "the seed changes the points";
  EXPECT_NE(a0, a1) << "dimension pairs are scrambled independently";
  b.startPixelSample(11, 20, 5);
  EXPECT_NE(a0, b.get2D()) << "neighbouring pixels are decorrelated";
}

TEST(SobolSampler, ValuesStayInTheHalfOpenUnitSquareAndAverageToAHalf) {
  SobolSampler s(9);
  double sum = 0.0;
  const int n = 1 << 14;
  for (int i = 0; i < n; ++i) {
    s.startPixelSample(0, 0, uint32_t(i));
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
