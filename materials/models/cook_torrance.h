// Cook-Torrance (Löw et al. 2012, eq. 3)  [Kd, Ks, m, η]
//   ρ = Kd/π + Ks · D · F(⟨V,H⟩; η) · G / (π ⟨L,N⟩⟨V,N⟩),   D = exp(−tan²θ_h / m²) / (m² cos⁴θ_h)
//   D is Beckmann without its 1/π; [convention] that 1/π sits in the denominator instead.
//   [convention] Fresnel at ⟨V,H⟩. G is the V-groove term.
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/fresnel.h"
#include "materials/models/half_vector.h"
#include "materials/models/vgroove.h"
#include "materials/models/common_params.h"

#include <cmath>

namespace glossy {

struct CookTorrance {
  static constexpr std::string_view kName = "cook-torrance";
  static constexpr std::string_view kLabel = "Cook-Torrance";
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"m", ParamKind::Scalar, ParamBound::Positive, "Beckmann roughness m"},
      params::kEta,
  };
  static CookTorrance fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("ks"), p.scalar("m"), p.scalar("eta")};
  }

  Rgb kd{0.0}, ks{0.0};
  double m = 0.1, eta = 1.5;

  Rgb eval(const Vec3& L, const Vec3& V) const {
    if (L.z <= 0.0 || V.z <= 0.0) return Rgb(0.0);
    const HalfVector h(L, V);
    const double m2 = m * m;
    const double cos2 = h.cosTheta * h.cosTheta;
    const double d = std::exp(-h.tan2Theta / m2) / (m2 * cos2 * cos2);
    const double g = vgrooveG(h.cosTheta, L.z, V.z, h.cosVH);
    const double spec = d * fresnelCookTorrance(h.cosVH, eta) * g / (kPi * L.z * V.z);
    return kd * kInvPi + ks * spec;
  }
  BrdfSample sample(const Vec3& V, double /*uLobe*/, Vec2 u) const { return sampleCosineLobe(*this, V, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return V.z > 0.0 ? cosineHemispherePdf(L) : 0.0; }
};

}  // namespace glossy
