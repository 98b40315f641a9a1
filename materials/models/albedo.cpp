#include "materials/models/albedo.h"

#include <array>
#include <cmath>

namespace glossy {

namespace {

constexpr int kNodes = 24;
constexpr int kPanels = 64;  // [2^-64, 2^-63], …, [½, 1], plus [0, 2^-64]

struct GaussLegendre {
  std::array<double, kNodes> x, w;  // on [-1, 1]
  GaussLegendre() {
    for (int i = 0; i < kNodes; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (kNodes + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = 0.0;
        for (int j = 1; j <= kNodes; ++j) {
          const double p2 = p1;
          p1 = p0;
          p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
        }
        dp = kNodes * (z * p0 - p1) / (z * z - 1.0);
        const double dz = p0 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

}  // namespace

Rgb albedoAtNormalIncidence(const Brdf& brdf) {
  static const GaussLegendre gl;
  const Vec3 V(0.0, 0.0, 1.0);
  Rgb sum(0.0);
  auto panel = [&](double a, double b) {
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    for (int i = 0; i < kNodes; ++i) {
      const double x = mid + half * gl.x[i];
      const Vec3 L(std::sqrt(x * (2.0 - x)), 0.0, 1.0 - x);
      sum += eval(brdf, L, V) * ((1.0 - x) * gl.w[i] * half);
    }
  };
  panel(0.0, std::ldexp(1.0, -kPanels));
  for (int k = kPanels; k >= 1; --k) panel(std::ldexp(1.0, -k), std::ldexp(1.0, -k + 1));
  return 2.0 * kPi * sum;
}

}  // namespace glossy
