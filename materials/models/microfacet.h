// Microfacet model (Löw et al. 2012, eq. 2)  [Kd, A, B, C, η]
//   ρ = Kd/π + A (1 + B(1 − ⟨N,H⟩))^(−C) · F(⟨V,H⟩; η) · G / (π ⟨L,N⟩⟨V,N⟩)
// i.e. S(f) = A/(1+Bf²)^C at f = sqrt(1 − ⟨N,H⟩), with the V-groove G.
//   [convention] the 1/π is not in the supplement's printed formula; the published parameters need it
//                (without it the fits are 2–4× brighter than the other fits of the same material).
//   [convention] Fresnel at ⟨V,H⟩, never ⟨N,H⟩.
#pragma once

#include "materials/models/abc_profile.h"
#include "materials/models/brdf_sample.h"
#include "materials/models/fresnel.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"
#include "materials/models/common_params.h"

#include <cmath>

namespace glossy {

struct Microfacet {
  static constexpr std::string_view kName = "microfacet";
  static constexpr std::string_view kLabel = "Microfacet";
  static constexpr std::string_view kConventions = "1/pi in the specular denominator, Fresnel at <V,H>";
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kAbcA, params::kAbcB, params::kAbcC,
      params::kEta,
  };
  static Microfacet fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("a"), p.scalar("b"), p.scalar("c"), p.scalar("eta")};
  }

  Rgb kd{0.0}, a{0.0};
  double b = 0.0, c = 1.0, eta = 1.5;

  // The specular lobe ρ_s = (1 + B(1 − ⟨N,H⟩))^(−C) F G / (π⟨L,N⟩⟨V,N⟩), ρ = Kd/π + A ρ_s; shape = {B, C, η}.
  static constexpr std::string_view kScaleKey = "a";
  static constexpr ShapeParam kShape[] = {params::kFitAbcB, params::kFitAbcC, params::kFitEta};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp, std::log1p;
    const T s = exp(-shape[1] * log1p(shape[0] * g.h.oneMinusCosTheta));
    return s * fresnelCookTorrance(g.h.cosVH, shape[2]) * (g.g / (kPi * g.cosL * g.cosV));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, a, {b, c, eta}); }

  // Sampling: x = 1 − cos θ_h with density ∝ (1 + Bx)^(−C) on [0, 1], φ_h uniform, L = reflect(V, H);
  // pdf(L) = pdf_h / (4⟨V,H⟩), pdf_h = S(x) / (2π ∫₀¹ S).
  double specularProbability() const {
    // Head-on lobe albedo ≈ 8 A F(1) ∫ S(x) dx over H within 45° of N (G ≈ 1).
    return lobeProbability(8.0 * meanOf(a) * fresnelAtNormalIncidence(eta) * AbcProfile{b, c}.integral(1.0 - std::sqrt(0.5)), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const {
    return reflectAboutHalfVector(V, AbcProfile{b, c}.invert(u.x, 1.0), 2.0 * kPi * u.y, L);
  }
  double lobePdf(const Vec3& L, const Vec3& V) const {
    const HalfVector h(L, V);
    if (h.cosVH <= 0.0) return 0.0;
    const AbcProfile s{b, c};
    return s(h.oneMinusCosTheta) / (s.integral(1.0) * 2.0 * kPi * 4.0 * h.cosVH);
  }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
  // sample and evalPdf are their batch forms' one lane, as Cook-Torrance's (cook_torrance.h).
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const {
    BrdfSample s;
    sampleMixtureBatch(*this, &V, &uLobe, &u, &s, 1);
    return s;
  }
  BrdfValue evalPdf(const Vec3& L, const Vec3& V) const {
    BrdfValue v;
    evalPdfBatch(&L, &V, &v, 1);
    return v;
  }
  // The batch forms (brdf_sample.h): sampleLobe's 1 − cos θ_h and evalPdf, their log1p, expm1 and exp
  // computed for all lanes at once, and the profile's integrals once per batch (microfacet.cpp).
  void lobeOneMinusCosBatch(const Vec2* u, const bool* lobe, double* oneMinusCos, int n) const;
  void evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n) const;
};

}  // namespace glossy
