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
    return lobe(g, exp(-shape[1] * log1p(shape[0] * g.h.oneMinusCosTheta)), shape[2]);
  }
  // The same, given the profile (1 + B(1 − cos θ_h))^(−C) (which evalPdf shares with the pdf).
  template <class T>
  static T lobe(const LobeGeometry& g, const T& profile, const T& eta) {
    return profile * fresnelCookTorrance(g.h.cosVH, eta) * (g.g / (kPi * g.cosL * g.cosV));
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
  // pdf_L = pdf_h / (4⟨V,H⟩), given the profile at θ_h.
  double lobePdf(const HalfVector& h, double profile) const {
    return h.cosVH <= 0.0 ? 0.0 : profile / (AbcProfile{b, c}.integral(1.0) * 2.0 * kPi * 4.0 * h.cosVH);
  }
  double lobePdf(const Vec3& L, const Vec3& V) const {
    const HalfVector h(L, V);
    return lobePdf(h, AbcProfile{b, c}(h.oneMinusCosTheta));
  }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
  // ρ and the mixture's density at L, the profile computed once for both.
  BrdfValue evalPdf(const Vec3& L, const Vec3& V) const {
    if (L.z <= 0.0 || V.z <= 0.0) return {};
    const LobeGeometry g(L, V);
    const double profile = AbcProfile{b, c}(g.h.oneMinusCosTheta), p = specularProbability();
    return {kd * kInvPi + a * lobe(g, profile, eta), mixtureDensity(p, p > 0.0 ? lobePdf(g.h, profile) : 0.0, L)};
  }

  // The batch forms the path tracer calls (brdf_sample.h): sampleLobe's 1 − cos θ_h and evalPdf for many
  // lanes, the same formulas as loops the compiler vectorises, their log1p, expm1 and exp computed for all
  // lanes at once by lanes:: and the profile's integrals once per batch (microfacet.cpp); equal to the
  // forms above up to the vector math's last bits.
  void lobeOneMinusCosBatch(const Vec2* u, const bool* lobe, double* oneMinusCos, int n) const;
  void evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n) const;
};

}  // namespace glossy
