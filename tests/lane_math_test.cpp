// lanes:: (libmvec over arrays): libm's values to within a few ulp, for every batch length (whole vectors
// and padded tails), and a lane's value independent of its batch.
#include "materials/core/lane_math.h"
#include "materials/core/types.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace glossy;

namespace {

// Arguments the environment and the samplers pass: every quadrant, the axes, a pole, tiny and large angles.
struct Inputs {
  std::vector<double> y, x, angle;
  explicit Inputs(int n) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const double special[][2] = {{0.0, 1.0}, {0.0, -1.0}, {1.0, 0.0}, {-1.0, 0.0}, {1e-300, 1.0}, {-0.0, -1.0}};
    for (int i = 0; i < n; ++i) {
      const bool fixed = i < int(std::size(special));
      y.push_back(fixed ? special[i][0] : uniform(rng));
      x.push_back(fixed ? special[i][1] : uniform(rng));
      angle.push_back(i % 7 == 0 ? 1e-9 * i : 4.0 * kPi * uniform(rng));
    }
  }
};

}  // namespace

// Both variants: AVX2 where the CPU has it, and the SSE2 one every x86-64 has.
class LaneMath : public ::testing::TestWithParam<lanes::Isa> {
 protected:
  void SetUp() override {
    saved_ = lanes::isa();
    if (!lanes::setIsa(GetParam())) GTEST_SKIP() << "this CPU has no AVX2";
  }
  void TearDown() override { lanes::setIsa(saved_); }
  lanes::Isa saved_ = lanes::Isa::Sse2;
};

TEST_P(LaneMath, MatchesLibmForEveryBatchLength) {
  for (int n = 1; n <= 70; ++n) {
    const Inputs in(n);
    std::vector<double> a(n), s(n), c(n);
    lanes::atan2(in.y.data(), in.x.data(), a.data(), n);
    lanes::sinCos(in.angle.data(), s.data(), c.data(), n);
    for (int i = 0; i < n; ++i) {
      const double exact = std::atan2(in.y[i], in.x[i]);
      const double ulp = std::nextafter(std::abs(exact), INFINITY) - std::abs(exact);
      ASSERT_NEAR(a[i], exact, 4.0 * ulp)
          << "atan2(" << in.y[i] << ", " << in.x[i] << "), lane " << i << " of " << n;
      ASSERT_NEAR(s[i], std::sin(in.angle[i]), 1e-15) << "sin " << in.angle[i];
      ASSERT_NEAR(c[i], std::cos(in.angle[i]), 1e-15) << "cos " << in.angle[i];
    }
    // The signs of the axes and of zero survive: the lat-long seam depends on them.
    if (n >= 6) {
      EXPECT_EQ(a[0], 0.0);
      EXPECT_EQ(a[1], kPi);
      EXPECT_EQ(a[5], -kPi);
    }
  }
}

// exp over the arguments the Beckmann term passes (−tan²θ_h / m², down to underflow), log1p over −u for
// u in [0, 1) (the Beckmann sampler's), and expm1, all within a few ulp of libm.
TEST_P(LaneMath, ExpLog1pAndExpm1MatchLibmForEveryBatchLength) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 1; n <= 70; ++n) {
    std::vector<double> a(n), u(n), e(n), l(n);
    for (int i = 0; i < n; ++i) {
      a[i] = i == 0 ? 0.0 : i == 1 ? -800.0 : -std::pow(10.0, 6.0 * unit(rng) - 3.0);
      u[i] = i == 0 ? -0.0 : i == 1 ? -(1.0 - 0x1p-53) : -unit(rng);
    }
    lanes::exp(a.data(), e.data(), n);
    lanes::log1p(u.data(), l.data(), n);
    // expm1 over what the ABC sampler passes: 0 to ln(1 + B) ≈ 16, with arguments down to 1e-12.
    std::vector<double> x(n), m(n);
    for (int i = 0; i < n; ++i) x[i] = i == 0 ? 0.0 : i == 1 ? 16.0 : std::pow(10.0, 13.2 * unit(rng) - 12.0);
    lanes::expm1(x.data(), m.data(), n);
    for (int i = 0; i < n; ++i) {
      const double exactE = std::exp(a[i]), exactL = std::log1p(u[i]), exactM = std::expm1(x[i]);
      ASSERT_NEAR(e[i], exactE, 4.0 * std::abs(exactE) * 0x1p-52) << "exp(" << a[i] << "), lane " << i << " of " << n;
      ASSERT_NEAR(l[i], exactL, 4.0 * std::abs(exactL) * 0x1p-52) << "log1p(" << u[i] << "), lane " << i << " of " << n;
      ASSERT_NEAR(m[i], exactM, 4.0 * std::abs(exactM) * 0x1p-52) << "expm1(" << x[i] << "), lane " << i << " of " << n;
    }
    EXPECT_EQ(m[0], 0.0);
    EXPECT_EQ(e[0], 1.0);
    if (n >= 2) {
      EXPECT_EQ(e[1], 0.0);
    }
  }
}

TEST_P(LaneMath, ALaneGetsTheSameValueInAnyBatch) {
  const Inputs in(37);
  std::vector<double> all(37), sAll(37), cAll(37);
  lanes::atan2(in.y.data(), in.x.data(), all.data(), 37);
  lanes::sinCos(in.angle.data(), sAll.data(), cAll.data(), 37);
  std::vector<double> minusX(37), eAll(37), lAll(37), mAll(37);
  for (int i = 0; i < 37; ++i) minusX[i] = -std::abs(in.x[i]);
  lanes::exp(in.y.data(), eAll.data(), 37);
  lanes::log1p(minusX.data(), lAll.data(), 37);
  lanes::expm1(in.y.data(), mAll.data(), 37);
  for (int i = 0; i < 37; ++i) {
    double one = 0.0, s = 0.0, c = 0.0, e = 0.0, l = 0.0, m = 0.0;
    lanes::atan2(&in.y[i], &in.x[i], &one, 1);
    lanes::sinCos(&in.angle[i], &s, &c, 1);
    lanes::exp(&in.y[i], &e, 1);
    lanes::log1p(&minusX[i], &l, 1);
    lanes::expm1(&in.y[i], &m, 1);
    ASSERT_EQ(m, mAll[i]) << i;
    ASSERT_EQ(one, all[i]) << i;
    ASSERT_EQ(s, sAll[i]) << i;
    ASSERT_EQ(c, cAll[i]) << i;
    ASSERT_EQ(e, eAll[i]) << i;
    ASSERT_EQ(l, lAll[i]) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, LaneMath, ::testing::Values(lanes::Isa::Sse2, lanes::Isa::Avx2),
                         [](const ::testing::TestParamInfo<lanes::Isa>& info) {
                           return info.param == lanes::Isa::Avx2 ? std::string("avx2") : std::string("sse2");
                         });
