// The ABC lobe profile s ↦ (1 + B s)^(−C) (s = f², Löw et al.'s S(f) without A), its integral and the
// inverse of that integral: what the Microfacet (s = 1 − cos θ_h) and Smooth (s = ‖D_P‖²) samplers draw
// from. All in expm1/log1p form: B reaches 8.1e6 and C goes down to 0.014.
#pragma once

#include <cmath>

namespace glossy {

struct AbcProfile {
  double b, c;

  double operator()(double s) const { return std::exp(-c * std::log1p(b * s)); }

  // ∫₀ˢ (1 + B t)^(−C) dt = expm1((1 − C) log1p(B s)) / ((1 − C) B); log1p(B s)/B at C = 1; s at B = 0.
  double integral(double s) const {
    const double bs = b * s;
    if (bs < 1e-12) return s;
    const double l = std::log1p(bs), k = 1.0 - c;
    if (std::abs(k * l) < 1e-10) return l / b;  // C = 1 (to 1e-10 relative)
    return std::expm1(k * l) / (k * b);
  }

  // The s in [0, sMax] whose integral is xi · integral(sMax).
  double invert(double xi, double sMax) const {
    const double bs = b * sMax;
    if (bs < 1e-12) return xi * sMax;
    const double lMax = std::log1p(bs), k = 1.0 - c;
    if (std::abs(k * lMax) < 1e-10) return std::expm1(xi * lMax) / b;
    // (1 + B s)^(1−C) = 1 + xi ((1 + B sMax)^(1−C) − 1)
    return std::expm1(std::log1p(xi * std::expm1(k * lMax)) / k) / b;
  }
};

}  // namespace glossy
