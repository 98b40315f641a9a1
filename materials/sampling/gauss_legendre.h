// Gauss-Legendre quadrature nodes and weights on [−1, 1], N points, computed once by Newton's iteration on
// the Legendre polynomial: exact for polynomials up to degree 2N − 1. The albedo quadratures (materials/
// models/albedo.cpp, renderer/plot/directional_albedo.cpp) map them onto their panels.
#pragma once

#include "materials/core/types.h"

#include <array>
#include <cmath>

namespace glossy {

template <int N>
struct GaussLegendre {
  std::array<double, N> x, w;
  GaussLegendre() {
    for (int i = 0; i < N; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (N + 0.5)), dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = 0.0;
        for (int j = 1; j <= N; ++j) {
          const double p2 = p1;
          p1 = p0;
          p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
        }
        dp = N * (z * p0 - p1) / (z * z - 1.0);
        const double dz = p0 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      x[size_t(i)] = z;
      w[size_t(i)] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

}  // namespace glossy
