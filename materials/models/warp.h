// Warps from the unit square to sampling domains, with their densities. Shared by every BRDF's sampler.
#pragma once

#include "materials/core/types.h"

#include <algorithm>
#include <cmath>

namespace glossy {

// Shirley-Chiu concentric map: area-preserving and low-distortion, so stratified points stay stratified.
inline Vec2 squareToConcentricDisk(Vec2 u) {
  const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
  if (a == 0.0 && b == 0.0) return {0.0, 0.0};
  double r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4.0) * (b / a);
  } else {
    r = b;
    phi = kPi / 2.0 - (kPi / 4.0) * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Malley's method: the disk lifted to the hemisphere gives density cos θ / π (solid angle).
inline Vec3 squareToCosineHemisphere(Vec2 u) {
  const Vec2 d = squareToConcentricDisk(u);
  const double z = std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y));
  return {d.x, d.y, z};
}

inline double cosineHemispherePdf(const Vec3& w) { return w.z > 0.0 ? w.z * kInvPi : 0.0; }

}  // namespace glossy
