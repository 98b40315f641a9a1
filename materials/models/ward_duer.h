// Ward-Duer, isotropic, as Ngan, Durand & Matusik 2005 fitted it  [Kd, Ks, α]
//   ρ = Kd/π + Ks · exp(−tan²θ_h / α²) / (4π α² ⟨L,N⟩⟨V,N⟩)
// Ward's lobe with Dür's normalisation (2006): 1/(⟨L,N⟩⟨V,N⟩) in place of Ward's 1/√(⟨L,N⟩⟨V,N⟩), which
// brightens grazing reflection; bbm's `NganWardDuer` (bsdfmodel/wardduer.h, commit 9807fb38) evaluates it
// so. Conventions as Ward's (ward.h): α the slope RMS, tan²θ_h from the unnormalised L + V, Kd the fit's
// Lambertian albedo, no cos θ_L, 0 where bbm divides by zero at the horizon. Sampled as Ward's lobe: the
// same half-vector density, which bbm uses for it too.
#pragma once

#include "materials/models/ward.h"

namespace glossy {

struct WardDuer {
  static constexpr std::string_view kName = "ward-duer";
  static constexpr std::string_view kLabel = "Ward-Duer";
  static constexpr std::string_view kConventions = "Ngan 2005: 1/(4 pi a^2 cos cos), a the slope RMS";
  // As Ward's α (ward.h); the published fits span 0.00509 (hematite) to 0.5.
  static constexpr ParamSpec kParams[] = {params::kKd, params::kKs, ward_params::kAlpha};
  static WardDuer fromParams(const ParamSet& p) { return {p.rgb("kd"), p.rgb("ks"), p.scalar("alpha")}; }

  Rgb kd{0.0}, ks{0.0};
  double alpha = 0.1;

  // ρ = Kd/π + Ks ρ_s, ρ_s = exp(−tan²θ_h/α²) / (4π α² ⟨L,N⟩⟨V,N⟩); shape = {α}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr ShapeParam kShape[] = {ward_params::kAlphaShape};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp;
    const T a2 = shape[0] * shape[0];
    return exp(-g.h.tan2Theta / a2) / (4.0 * kPi * a2 * (g.cosL * g.cosV));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, ks, {alpha}); }

  // Head-on, the lobe's albedo is about Ks, as Ward's (the two normalisations agree at ⟨L,N⟩ = ⟨V,N⟩ = 1).
  double specularProbability() const { return lobeProbability(meanOf(ks), kd); }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const { return ward_sampling::sampleLobe(alpha, V, u, L); }
  double lobePdf(const Vec3& L, const Vec3& V) const { return ward_sampling::lobePdf(alpha, L, V); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
