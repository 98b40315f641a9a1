#include "materials/models/albedo.h"

#include "materials/sampling/gauss_legendre.h"

#include <array>
#include <cmath>

namespace glossy {

namespace {

constexpr int kNodes = 24;
constexpr int kPanels = 64;  // [2^-64, 2^-63], …, [½, 1], plus [0, 2^-64]

}  // namespace

Rgb albedoAtNormalIncidence(const Brdf& brdf) {
  static const GaussLegendre<kNodes> gl;
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
