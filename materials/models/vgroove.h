// V-groove shadowing/masking of Cook & Torrance (shared by the Microfacet and Cook-Torrance models):
//   G = min(1, 2⟨N,H⟩⟨N,V⟩/⟨V,H⟩, 2⟨N,H⟩⟨N,L⟩/⟨V,H⟩),  0 if ⟨V,H⟩ ≤ 0.
#pragma once

#include <algorithm>

namespace glossy {

// Without branches, so that loops over many lanes vectorise (the quotient of a lane with ⟨V,H⟩ ≤ 0 is
// computed and discarded).
inline double vgrooveG(double cosNH, double cosNL, double cosNV, double cosVH) {
  const double s = 2.0 * cosNH / cosVH;
  const double g = std::min(std::min(1.0, s * cosNV), s * cosNL);
  return cosVH <= 0.0 ? 0.0 : g;
}

}  // namespace glossy
