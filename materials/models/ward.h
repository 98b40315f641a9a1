// Ward, isotropic, as Ngan, Durand & Matusik 2005 fitted it  [Kd, Ks, α]
//   ρ = Kd/π + Ks · exp(−tan²θ_h / α²) / (4π α² √(⟨L,N⟩⟨V,N⟩))
// Ward's original normalisation (1992), which Ngan et al. use and bbm evaluates (bsdfmodel/ward.h, "NganWard",
// commit 9807fb38). [convention] α is the slope RMS itself, not α². [convention] tan²θ_h is taken from the
// unnormalised L + V, tan²θ_h = |h_p|²/h_z² (half_vector.h), which is what bbm's (Hu.x² + Hu.y²)/Hu.z² is.
// [convention] Kd is the fit's Lambertian albedo: the diffuse term is Kd/π, and ρ carries no cos θ_L.
// At ⟨L,N⟩ = 0 or ⟨V,N⟩ = 0 bbm divides by zero (its mask keeps z = 0); here ρ is 0 there, as everywhere
// below the horizon. Ks is the lobe's approximate albedo: exp(−tan²θ_h/α²)/(π α² cos³θ_h) is a density in
// H, and the 1/√(cos cos) stands in for the Jacobian 1/(4⟨V,H⟩) and the cos θ_L of the rendering equation.
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"

#include <cmath>

namespace glossy {

// The half-vector sampler Ward's lobe shares with Ward-Duer's (Walter 2005, "Notes on the Ward BRDF"): the
// density in H is exp(−tan²θ_h/α²) / (π α² cos³θ_h) (Beckmann's D cos θ_h), drawn by tan²θ_h = −α² ln(1 − ξ).
namespace ward_sampling {

// 1 − cos θ_h from tan²θ_h without cancellation: α reaches 0.005, where cos θ_h rounds to 1.
inline double oneMinusCosOfTan2(double tan2) {
  const double sec = std::sqrt(1.0 + tan2);
  return tan2 / (sec * (sec + 1.0));
}
inline bool sampleLobe(double alpha, const Vec3& V, Vec2 u, Vec3& L) {
  return reflectAboutHalfVector(V, oneMinusCosOfTan2(-alpha * alpha * std::log1p(-u.x)), 2.0 * kPi * u.y, L);
}
// pdf_L = pdf_H / (4⟨V,H⟩).
inline double lobePdf(double alpha, const Vec3& L, const Vec3& V) {
  const HalfVector h(L, V);
  if (h.cosVH <= 0.0) return 0.0;
  const double a2 = alpha * alpha, c = h.cosTheta;
  return std::exp(-h.tan2Theta / a2) / (kPi * a2 * c * c * c * 4.0 * h.cosVH);
}

}  // namespace ward_sampling

// The one parameter both Ward forms (this and ward_duer.h) share. α from 1e-4 (a MERL table's first θ_h bin is
// 1.9e-4 rad wide, so no measurement tells a sharper lobe from a mirror) to 10.
namespace ward_params {

inline constexpr ParamSpec kAlpha = {"alpha", ParamKind::Scalar, {1e-4, 10.0},
                                     "Ward roughness α (slope RMS, not α²)"};
inline constexpr double kAlphaStarts[] = {0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4};
inline constexpr ShapeParam kAlphaShape = {"alpha", FitScale::Log, 1e-4, 10.0, kAlphaStarts};

}  // namespace ward_params

struct Ward {
  static constexpr std::string_view kName = "ward";
  static constexpr std::string_view kLabel = "Ward";
  static constexpr std::string_view kConventions = "Ngan 2005: 1/(4 pi a^2 sqrt(cos cos)), a the slope RMS";
  // The published fits' α span 0.00576 (hematite) to 0.5, the bound of Ngan's search.
  static constexpr ParamSpec kParams[] = {params::kKd, params::kKs, ward_params::kAlpha};
  static Ward fromParams(const ParamSet& p) { return {p.rgb("kd"), p.rgb("ks"), p.scalar("alpha")}; }

  Rgb kd{0.0}, ks{0.0};
  double alpha = 0.1;

  // ρ = Kd/π + Ks ρ_s, ρ_s = exp(−tan²θ_h/α²) / (4π α² √(⟨L,N⟩⟨V,N⟩)); shape = {α}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr ShapeParam kShape[] = {ward_params::kAlphaShape};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp;
    const T a2 = shape[0] * shape[0];
    return exp(-g.h.tan2Theta / a2) / (4.0 * kPi * a2 * std::sqrt(g.cosL * g.cosV));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, ks, {alpha}); }

  double specularProbability() const { return lobeProbability(meanOf(ks), kd); }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const { return ward_sampling::sampleLobe(alpha, V, u, L); }
  double lobePdf(const Vec3& L, const Vec3& V) const { return ward_sampling::lobePdf(alpha, L, V); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
