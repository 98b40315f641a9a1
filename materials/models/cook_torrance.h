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

  // Sampling (Beckmann): tan²θ_h = −m² ln(1 − ξ), φ_h uniform; pdf_h = exp(−tan²θ_h/m²) / (π m² cos³θ_h).
  double specularProbability() const {
    // Head-on lobe albedo ≈ 4 Ks F(1): D cos θ_h integrates to π over the hemisphere (G ≈ 1).
    return lobeProbability(4.0 * meanOf(ks) * fresnelCookTorrance(1.0, eta), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const {
    const double tan2 = -m * m * std::log1p(-u.x);
    const double sec = std::sqrt(1.0 + tan2);  // 1 − cos θ = tan² / (sec (sec + 1)), no cancellation
    return reflectAboutHalfVector(V, tan2 / (sec * (sec + 1.0)), 2.0 * kPi * u.y, L);
  }
  double lobePdf(const Vec3& L, const Vec3& V) const {
    const HalfVector h(L, V);
    if (h.cosVH <= 0.0) return 0.0;
    const double m2 = m * m;
    return std::exp(-h.tan2Theta / m2) / (kPi * m2 * h.cosTheta * h.cosTheta * h.cosTheta * 4.0 * h.cosVH);
  }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
