// Ashikhmin-Shirley's specular lobe, isotropic, as Ngan, Durand & Matusik 2005 fitted it  [Kd, Ks, F0, n]
//   ρ = Kd/π + Ks · (n+1) ⟨N,H⟩ⁿ F(⟨L,H⟩) / (8π ⟨L,H⟩ max(⟨L,N⟩, ⟨V,N⟩)),   F(c) = F0 + (1 − F0)(1 − c)⁵
// A model of its own beside Löw et al.'s Ashikhmin-Shirley (ashikhmin_shirley.h), whose fits use the Cook-Torrance
// Fresnel of an index of refraction: here [convention] F is Schlick's with the reflectance F0 at normal
// incidence, and Ks scales the whole lobe, as bbm's `NganAshikhminShirley` (bsdfmodel/ngan.h: scaledmodel of
// ashikhminshirley with fresnel::schlick, commit 9807fb38) evaluates the fits; bbm's file key
// `fresnelReflectance` is F0. [convention] The Lambertian Kd/π replaces A-S's coupled diffuse term.
// ⟨N,H⟩ⁿ = exp(n log1p(−(1 − ⟨N,H⟩))): n reaches 7.82e4 (hematite).
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"
#include "materials/models/schlick.h"

#include <algorithm>
#include <cmath>

namespace glossy {

struct NganAshikhminShirley {
  static constexpr std::string_view kName = "ngan-ashikhmin-shirley";
  static constexpr std::string_view kLabel = "Ashikhmin-Shirley (Ngan)";
  static constexpr std::string_view kShortLabel = "AS (Ngan)";
  static constexpr std::string_view kConventions = "Ngan 2005: Schlick Fresnel of F0 at <L,H>";
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"f0", ParamKind::Scalar, {0.0, 1.0}, "Schlick's reflectance at normal incidence F0"},
      {"n", ParamKind::Scalar, {0.0, 1e8}, "Phong-like exponent n"},
  };
  static NganAshikhminShirley fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("ks"), p.scalar("f0"), p.scalar("n")};
  }

  Rgb kd{0.0}, ks{0.0};
  double f0 = 0.05, n = 1.0;

  // ρ = Kd/π + Ks ρ_s; shape = {n, F0}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr double kNStarts[] = {3.0, 10.0, 30.0, 100.0, 300.0, 1e3, 3e3, 1e4, 3e4, 1e5, 1e6};
  static constexpr double kF0Starts[] = {0.02, 0.2, 0.9};
  static constexpr ShapeParam kShape[] = {{"n", FitScale::Log, 1e-2, 1e8, kNStarts}, {"f0", FitScale::Log, 1e-4, 1.0, kF0Starts}};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp;
    if (g.h.cosVH <= 0.0) return T(0.0);
    const T cosN = exp(shape[0] * std::log1p(-g.h.oneMinusCosTheta));
    return (shape[0] + 1.0) * cosN * fresnelSchlick(g.h.cosVH, shape[1]) / (8.0 * kPi * g.h.cosVH * std::max(g.cosL, g.cosV));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, ks, {n, f0}); }

  // Sampling: Ashikhmin-Shirley's, cos θ_h = ξ^(1/(n+1)); pdf_h = (n+1)/(2π) cosⁿθ_h.
  double specularProbability() const {
    // Lobe albedo ≈ Ks F: the (n+1)/(2π) cosⁿ lobe integrates to 1 over H's hemisphere.
    return lobeProbability(meanOf(ks) * fresnelSchlickMean(f0), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const { return samplePowerCosineLobe(V, n, u, L); }
  double lobePdf(const Vec3& L, const Vec3& V) const { return powerCosineLobePdf(L, V, n); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
