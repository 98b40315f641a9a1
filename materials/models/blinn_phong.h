// Blinn-Phong on the half vector, normalised, as Ngan, Durand & Matusik 2005 fitted it  [Kd, Ks, n]
//   ρ = Kd/π + Ks · (n+2)/(2π) · ⟨N,H⟩ⁿ
// [choice] The half vector, not the mirror direction. bbm's `NganBlinnPhong` (bsdfmodel/ngan.h, commit 9807fb38)
// aliases the reflection-vector Phong, ρ_s = Ks (n+2)/(2π) max(⟨R(L),V⟩, 0)ⁿ, but Ngan's published n and Ks only
// make sense with ⟨N,H⟩ⁿ, the form the paper names and studies ("the specular lobe ... with respect to the
// half-vector"). Read on the half vector, the 86 fits agree with the Ward, Ashikhmin-Shirley and Cook-Torrance
// fits of the same materials; read on the mirror direction, every lobe is twice too narrow and a quarter of
// their energy. Figures (docs/models.md §8, medians over the 85 materials with both lobes non-zero): lobe width
// √(2/n) / the Ward fit's α is 0.88 on the half vector, 0.44 on the mirror direction; the lobe's head-on albedo
// over the Ward fit's is 0.93 on the half vector, 0.24 on the mirror direction (over the Ngan Ashikhmin-Shirley
// fit's 1.58 against 0.41, over the Ngan Cook-Torrance fit's 1.45 against 0.39). The mirror form's head-on
// albedo is exactly Ks; the half vector's is about 4 Ks, from dω_L = 4⟨V,H⟩ dω_H.
// [convention] Kd is the fit's Lambertian albedo, ρ carries no cos θ_L. ⟨N,H⟩ⁿ = exp(n log1p(−(1 − ⟨N,H⟩))):
// n reaches 1.21e5 (specular-violet-phenolic).
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"

#include <cmath>

namespace glossy {

struct BlinnPhong {
  static constexpr std::string_view kName = "blinn-phong";
  static constexpr std::string_view kLabel = "Blinn-Phong";
  static constexpr std::string_view kShortLabel = "BP";
  static constexpr std::string_view kConventions = "Ngan 2005: (n+2)/(2 pi) <N,H>^n on the half vector (bbm: mirror vector)";
  // n up to 1e8 as Ashikhmin-Shirley's n; the published fits span 1.45 to 1.21e5.
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"n", ParamKind::Scalar, {0.0, 1e8}, "Blinn-Phong exponent n (of ⟨N,H⟩)"},
  };
  static BlinnPhong fromParams(const ParamSet& p) { return {p.rgb("kd"), p.rgb("ks"), p.scalar("n")}; }

  Rgb kd{0.0}, ks{0.0};
  double n = 1.0;

  // ρ = Kd/π + Ks ρ_s, ρ_s = (n+2)/(2π) ⟨N,H⟩ⁿ; shape = {n}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr double kNStarts[] = {3.0, 10.0, 30.0, 100.0, 300.0, 1e3, 3e3, 1e4, 3e4, 1e5, 1e6};
  static constexpr ShapeParam kShape[] = {{"n", FitScale::Log, 1e-2, 1e8, kNStarts}};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp;
    return (shape[0] + 2.0) / (2.0 * kPi) * exp(shape[0] * std::log1p(-g.h.oneMinusCosTheta));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, ks, {n}); }

  // Sampling: the half-vector cosⁿ lobe, cos θ_h = ξ^(1/(n+1)), pdf_h = (n+1)/(2π) cosⁿθ_h (Ashikhmin-Shirley's).
  double specularProbability() const {
    // Head-on lobe albedo ≈ 4 Ks: (n+2)/(2π) cosⁿθ_h integrates to about 1 over H, and dω_L = 4⟨V,H⟩ dω_H.
    return lobeProbability(4.0 * meanOf(ks), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const { return samplePowerCosineLobe(V, n, u, L); }
  double lobePdf(const Vec3& L, const Vec3& V) const { return powerCosineLobePdf(L, V, n); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
