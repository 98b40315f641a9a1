// Sampling the unit square in proportion to a bilinear function, given by its four corner values: within
// an environment map's cell, the density the light's bilinear lookup asks for. A piecewise-constant
// density over the cells leaves the radiance's own variation inside each cell (up to 4× its mean where a
// bright texel meets dark ones) in every light sample's weight; drawn within the cell by the bilinear
// function, the weight L/pdf is nearly constant across it.
//
// The warp inverts the marginal over y, linear in y, then the conditional over x given y, linear in x:
// each coordinate's map is monotone, so a stratified u stays stratified within the square.
#pragma once

#include "materials/core/types.h"

#include <algorithm>
#include <cmath>

namespace glossy {

// The corner values, non-negative: f(x, y) = (1−x)(1−y)·v00 + x(1−y)·v10 + (1−x)y·v01 + xy·v11. A plain
// aggregate, always built whole (BilinearPatch{} is all zeros): batch callers keep arrays of them that
// are not zeroed per call.
struct BilinearPatch {
  double v00, v10, v01, v11;

  double mean() const { return 0.25 * (v00 + v10 + v01 + v11); }
  double value(Vec2 p) const {
    return (1.0 - p.y) * ((1.0 - p.x) * v00 + p.x * v10) + p.y * ((1.0 - p.x) * v01 + p.x * v11);
  }

  // The density of sample() at p in the square: f(p) / mean f. A patch of zeros is sampled uniformly.
  double density(Vec2 p) const {
    const double m = mean();
    return m > 0.0 ? value(p) / m : 1.0;
  }

  // The point of density density(p) at u in [0,1]².
  Vec2 sample(Vec2 u) const {
    const double y = sampleY(u.y);
    return {sampleX(u.x, y), y};
  }
  // Its two steps, for callers that take many patches one step at a time: y from the marginal, then x
  // from the conditional at that y.
  double sampleY(double uy) const { return mean() > 0.0 ? sampleLinear(uy, v00 + v10, v01 + v11) : uy; }
  double sampleX(double ux, double y) const {
    return mean() > 0.0 ? sampleLinear(ux, (1.0 - y) * v00 + y * v01, (1.0 - y) * v10 + y * v11) : ux;
  }

  // The t in [0, 1] at which the CDF of the density ∝ (1−t)·a + t·b reaches u. The CDF is the quadratic
  // (a·t + (b−a)·t²/2) / ((a+b)/2); its root, written u(a+b) / (a + √((1−u)a² + u·b²)), has no
  // cancellation when a ≈ b (where the textbook form divides by b − a).
  static double sampleLinear(double u, double a, double b) {
    const double denominator = a + std::sqrt((1.0 - u) * a * a + u * b * b);
    if (!(denominator > 0.0)) return u;  // a = 0 and u·b² = 0: t = u is as good as any
    return std::clamp(u * (a + b) / denominator, 0.0, 1.0);
  }
};

}  // namespace glossy
