// Fresnel factor of Cook & Torrance 1982 (unpolarised light, dielectric with index of refraction eta),
// the one all four Löw et al. models were fitted with:
//   g = sqrt(eta² + c² − 1),  F = ½ ((g−c)/(g+c))² [1 + ((c(g+c) − 1)/(c(g−c) + 1))²]
// c is the cosine of the angle of incidence on the facet (spec: ⟨V,H⟩ for the microfacet-style models,
// the projected cos θ_d for the Smooth model). F(1) = ((eta−1)/(eta+1))², F(0) = 1.
// A template in eta so that the fitter can differentiate it (T = ceres::Jet); c is geometry, always double.
#pragma once

#include <cmath>

namespace glossy {

template <class T>
T fresnelCookTorrance(double c, const T& eta) {
  using std::sqrt;
  // Selects rather than branches, so that loops over many lanes vectorise.
  c = c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
  const T radicand = eta * eta + (c * c - 1.0);
  const T g = sqrt(radicand < 0.0 ? T(0.0) : radicand);
  const T a = (g - c) / (g + c);
  const T b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

// F(1) in closed form, ((η − 1)/(η + 1))²: the samplers' lobe probabilities read it at every vertex.
inline double fresnelAtNormalIncidence(double eta) {
  const double r = (eta - 1.0) / (eta + 1.0);
  return r * r;
}

}  // namespace glossy
