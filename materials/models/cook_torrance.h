// Cook-Torrance (Löw et al. 2012, eq. 3)  [Kd, Ks, m, η]
//   ρ = Kd/π + Ks · D · F(⟨V,H⟩; η) · G / (π ⟨L,N⟩⟨V,N⟩),   D = exp(−tan²θ_h / m²) / (m² cos⁴θ_h)
//   D is Beckmann without its 1/π; [convention] that 1/π sits in the denominator instead.
//   [convention] Fresnel at ⟨V,H⟩. G is the V-groove term.
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/fresnel.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"
#include "materials/models/common_params.h"

#include <cmath>

namespace glossy {

struct CookTorrance {
  static constexpr std::string_view kName = "cook-torrance";
  static constexpr std::string_view kLabel = "Cook-Torrance";
  static constexpr double kFitCost = 1.5;  // half as long again as Microfacet: docs/cluster.md
  static constexpr std::string_view kShortLabel = "CT";
  static constexpr std::string_view kConventions = "1/pi in the specular denominator (not in D), Fresnel at <V,H>";
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"m", ParamKind::Scalar, {1e-4, 10.0}, "Beckmann roughness m"},
      params::kEta,
  };
  static CookTorrance fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("ks"), p.scalar("m"), p.scalar("eta")};
  }

  Rgb kd{0.0}, ks{0.0};
  double m = 0.1, eta = 1.5;

  // The specular lobe ρ_s = D F G / (π⟨L,N⟩⟨V,N⟩), ρ = Kd/π + Ks ρ_s; shape = {m, η}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr double kMStarts[] = {0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8};
  static constexpr ShapeParam kShape[] = {{"m", FitScale::Log, 1e-4, 10.0, kMStarts}, params::kFitEta};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp;
    const T m2 = shape[0] * shape[0];
    return lobe(g, m2, exp(-g.h.tan2Theta / m2), shape[1]);
  }
  // The same, given m² and beckmann = exp(−tan²θ_h / m²) (which evalPdf shares with the pdf).
  template <class T>
  static T lobe(const LobeGeometry& g, const T& m2, const T& beckmann, const T& eta) {
    const double cos2 = g.h.cosTheta * g.h.cosTheta;
    const T d = beckmann / (m2 * (cos2 * cos2));
    return d * fresnelCookTorrance(g.h.cosVH, eta) * (g.g / (kPi * g.cosL * g.cosV));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const {
    if (L.z <= 0.0 || V.z <= 0.0) return Rgb(0.0);
    const double shape[] = {m, eta};
    return kd * kInvPi + ks * lobe(LobeGeometry(L, V), shape);
  }

  // Sampling (Beckmann): tan²θ_h = −m² ln(1 − ξ), φ_h uniform; pdf_h = exp(−tan²θ_h/m²) / (π m² cos³θ_h).
  double specularProbability() const {
    // Head-on lobe albedo ≈ 4 Ks F(1): D cos θ_h integrates to π over the hemisphere (G ≈ 1).
    return lobeProbability(4.0 * meanOf(ks) * fresnelAtNormalIncidence(eta), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const {
    return reflectAboutHalfVector(V, oneMinusCosOfTan2(-m * m * std::log1p(-u.x)), 2.0 * kPi * u.y, L);
  }
  // 1 − cos θ = tan²θ / (sec θ (sec θ + 1)), without cancellation.
  static double oneMinusCosOfTan2(double tan2) {
    const double sec = std::sqrt(1.0 + tan2);
    return tan2 / (sec * (sec + 1.0));
  }
  // pdf_L = pdf_h / (4⟨V,H⟩), given beckmann = exp(−tan²θ_h / m²).
  double lobePdf(const HalfVector& h, double beckmann) const {
    const double pdf = beckmann / (kPi * (m * m) * h.cosTheta * h.cosTheta * h.cosTheta * 4.0 * h.cosVH);
    return h.cosVH <= 0.0 ? 0.0 : pdf;  // a select, not a branch: evalPdfBatch's loop vectorises
  }
  double lobePdf(const Vec3& L, const Vec3& V) const {
    const HalfVector h(L, V);
    return lobePdf(h, std::exp(-h.tan2Theta / (m * m)));
  }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
  // ρ and the mixture's density at L, D's exponential computed once for both.
  BrdfValue evalPdf(const Vec3& L, const Vec3& V) const {
    if (L.z <= 0.0 || V.z <= 0.0) return {};
    const LobeGeometry g(L, V);
    const double m2 = m * m, beckmann = std::exp(-g.h.tan2Theta / m2), p = specularProbability();
    return {kd * kInvPi + ks * lobe(g, m2, beckmann, eta), mixtureDensity(p, p > 0.0 ? lobePdf(g.h, beckmann) : 0.0, L)};
  }

  // The batch forms the path tracer calls (brdf_sample.h): sampleLobe's 1 − cos θ_h and evalPdf for many
  // lanes, the same formulas as loops the compiler vectorises, their log1p and exp computed for all lanes
  // at once by lanes:: (cook_torrance.cpp); equal to the forms above up to the vector math's last bits.
  void lobeOneMinusCosBatch(const Vec2* u, const bool* lobe, double* oneMinusCos, int n) const;
  void evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n) const;
};

}  // namespace glossy
