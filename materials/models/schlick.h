// Schlick's Fresnel approximation from the reflectance at normal incidence F0 (not an index of refraction):
//   F(c) = F0 + (1 − F0)(1 − c)⁵
// The Fresnel factor of Ngan et al. 2005's Ashikhmin-Shirley and Cook-Torrance fits (and bbm's
// fresnel_schlick.h), where the Löw et al. models use the Cook-Torrance Fresnel of an η (fresnel.h).
#pragma once

#include <algorithm>

namespace glossy {

template <class T>
T fresnelSchlick(double c, const T& f0) {
  const double m = 1.0 - std::clamp(c, 0.0, 1.0), m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Its cosine-weighted mean over the hemisphere, F0 + (1 − F0)/21 (∫₀¹ (1 − c)⁵ 2c dc = 1/21): the lobe's albedo
// in the samplers' mixture weights, never 0 where F0 = 0 but grazing light still reflects.
inline double fresnelSchlickMean(double f0) { return f0 + (1.0 - f0) / 21.0; }

}  // namespace glossy
