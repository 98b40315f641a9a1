// The half-vector quantities of the microfacet-style models, computed without cancellation.
// With h = L + V (unnormalised) and h_p = (h_x, h_y):
//   1 − cos θ_h = |h_p|² / (|h| (|h| + h_z))      (never 1 − ⟨N,H⟩ by subtraction: AS n reaches 6.2e5)
//   tan² θ_h    = |h_p|² / h_z²
// Callers guarantee L_z > 0 and V_z > 0, so h_z > 0.
#pragma once

#include "materials/core/types.h"

#include <cmath>

namespace glossy {

struct HalfVector {
  double cosTheta;          // ⟨N,H⟩
  double oneMinusCosTheta;  // 1 − ⟨N,H⟩
  double tan2Theta;         // tan² θ_h
  double cosVH;             // ⟨V,H⟩ = ⟨L,H⟩

  HalfVector(const Vec3& L, const Vec3& V) {
    const Vec3 h = L + V;
    const double p2 = h.x * h.x + h.y * h.y;
    const double len = std::sqrt(p2 + h.z * h.z), invLen = 1.0 / len;
    cosTheta = h.z * invLen;
    oneMinusCosTheta = p2 / (len * (len + h.z));
    tan2Theta = p2 / (h.z * h.z);
    cosVH = (V.x * h.x + V.y * h.y + V.z * h.z) * invLen;
  }
};

}  // namespace glossy
