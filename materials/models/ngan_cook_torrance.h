// Cook-Torrance as Ngan, Durand & Matusik 2005 fitted it  [Kd, Ks, F0, m]
//   ρ = Kd/π + Ks · D · G · F(⟨V,H⟩) / (π ⟨L,N⟩⟨V,N⟩)
//   D = exp(−tan²θ_h / m²) / (π m² cos⁴θ_h)        (Beckmann, normalised: ∫ D cos θ_h dω_h = 1)
//   G = min(1, 2⟨N,H⟩⟨N,V⟩/⟨V,H⟩, 2⟨N,H⟩⟨N,L⟩/⟨V,H⟩) (V-groove),   F(c) = F0 + (1 − F0)(1 − c)⁵ (Schlick)
// A model of its own beside Löw et al.'s Cook-Torrance (cook_torrance.h): [convention] the lobe's constant is
// 1/π² — one 1/π in the normalised D, one in the denominator — where Löw's D has none; [convention] F is
// Schlick's of the reflectance F0, not the Cook-Torrance Fresnel of an η. That is bbm's `NganCookTorrance`
// (bsdfmodel/ngan.h: microfacet<beckmann, vgroove, schlick, Cook>, commit 9807fb38), whose file key `eta` holds
// F0 despite its name. The extra 1/π is what the fits mean: with it the lobes' energy matches the Ngan
// Ashikhmin-Shirley fits of the same materials (median Ks F0 (4/π) / Ward's Ks 0.65, against 0.60 for A-S);
// without it the ratio would be 2.0. [convention] Kd is the fit's Lambertian albedo, ρ carries no cos θ_L.
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"
#include "materials/models/schlick.h"
#include "materials/models/ward.h"

#include <cmath>

namespace glossy {

struct NganCookTorrance {
  static constexpr std::string_view kName = "ngan-cook-torrance";
  static constexpr std::string_view kLabel = "Cook-Torrance (Ngan)";
  static constexpr std::string_view kShortLabel = "CT (Ngan)";
  static constexpr std::string_view kConventions = "Ngan 2005: normalised Beckmann D and 1/pi (1/pi^2 in all), Schlick Fresnel of F0";
  // m as Löw's Cook-Torrance m (cook_torrance.h); the published fits span 0.00512 (hematite) to 0.943.
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"f0", ParamKind::Scalar, {0.0, 1.0}, "Schlick's reflectance at normal incidence F0"},
      {"m", ParamKind::Scalar, {1e-4, 10.0}, "Beckmann roughness m"},
  };
  static NganCookTorrance fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("ks"), p.scalar("f0"), p.scalar("m")};
  }

  Rgb kd{0.0}, ks{0.0};
  double f0 = 0.05, m = 0.1;

  // ρ = Kd/π + Ks ρ_s; shape = {m, F0}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr double kMStarts[] = {0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8};
  static constexpr double kF0Starts[] = {0.02, 0.2, 0.9};
  static constexpr ShapeParam kShape[] = {{"m", FitScale::Log, 1e-4, 10.0, kMStarts}, {"f0", FitScale::Log, 1e-4, 1.0, kF0Starts}};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp;
    const T m2 = shape[0] * shape[0];
    const double cos2 = g.h.cosTheta * g.h.cosTheta;
    const T d = exp(-g.h.tan2Theta / m2) / (kPi * m2 * (cos2 * cos2));
    return d * fresnelSchlick(g.h.cosVH, shape[1]) * (g.g / (kPi * g.cosL * g.cosV));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, ks, {m, f0}); }

  // Sampling: Beckmann's D cos θ_h, tan²θ_h = −m² ln(1 − ξ), Ward's half-vector sampler (ward.h) with α = m.
  double specularProbability() const {
    // Lobe albedo ≈ (4/π) Ks F: D cos θ_h integrates to 1 and dω_L = 4⟨V,H⟩ dω_H, over π of the denominator.
    return lobeProbability(4.0 * kInvPi * meanOf(ks) * fresnelSchlickMean(f0), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const { return ward_sampling::sampleLobe(m, V, u, L); }
  double lobePdf(const Vec3& L, const Vec3& V) const { return ward_sampling::lobePdf(m, L, V); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
