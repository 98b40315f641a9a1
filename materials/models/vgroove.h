// V-groove shadowing/masking of Cook & Torrance (shared by the Microfacet and Cook-Torrance models):
//   G = min(1, 2⟨N,H⟩⟨N,V⟩/⟨V,H⟩, 2⟨N,H⟩⟨N,L⟩/⟨V,H⟩),  0 if ⟨V,H⟩ ≤ 0.
#pragma once

#include <algorithm>

namespace glossy {

inline double vgrooveG(double cosNH, double cosNL, double cosNV, double cosVH) {
  if (cosVH <= 0.0) return 0.0;
  const double s = 2.0 * cosNH / cosVH;
  return std::min({1.0, s * cosNV, s * cosNL});
}

}  // namespace glossy
