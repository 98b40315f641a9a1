// Warps from the unit square to sampling domains, with their densities. Shared by every BRDF's sampler.
#pragma once

#include "materials/core/types.h"

#include <algorithm>
#include <cmath>

namespace glossy {

// Shirley-Chiu concentric map: area-preserving and low-distortion, so stratified points stay stratified.
// The point is (r cos φ, r sin φ); the batch samplers take r and φ and compute the cosines for many
// points at once.
inline void squareToConcentricDiskPolar(Vec2 u, double& r, double& phi) {
  const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
  if (a == 0.0 && b == 0.0) {
    r = phi = 0.0;
  } else if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4.0) * (b / a);
  } else {
    r = b;
    phi = kPi / 2.0 - (kPi / 4.0) * (a / b);
  }
}
inline Vec2 squareToConcentricDisk(Vec2 u) {
  double r, phi;
  squareToConcentricDiskPolar(u, r, phi);
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Malley's method: the disk lifted to the hemisphere gives density cos θ / π (solid angle).
inline Vec3 diskToCosineHemisphere(const Vec2& d) {
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}
inline Vec3 squareToCosineHemisphere(Vec2 u) { return diskToCosineHemisphere(squareToConcentricDisk(u)); }

inline double cosineHemispherePdf(const Vec3& w) { return w.z > 0.0 ? w.z * kInvPi : 0.0; }

}  // namespace glossy
