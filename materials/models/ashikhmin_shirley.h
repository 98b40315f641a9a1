// Ashikhmin-Shirley, isotropic (Löw et al. 2012, eq. 4)  [Kd, Ks, n, η]
//   ρ = Kd/π + Ks · (n+1) ⟨N,H⟩ⁿ F(⟨V,H⟩; η) / (8π ⟨V,H⟩ max(⟨L,N⟩, ⟨V,N⟩))
// Lambertian diffuse (not AS's coupled diffuse term) and the Cook-Torrance Fresnel with an index of
// refraction (not Schlick), as the fits were made. ⟨N,H⟩ⁿ = exp(n log1p(−(1 − ⟨N,H⟩))): n reaches 6.2e5.
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/fresnel.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"
#include "materials/models/common_params.h"

#include <algorithm>
#include <cmath>

namespace glossy {

struct AshikhminShirley {
  static constexpr std::string_view kName = "ashikhmin-shirley";
  static constexpr std::string_view kLabel = "Ashikhmin-Shirley";
  static constexpr double kFitCost = 1.5;  // half as long again as Microfacet: docs/cluster.md
  static constexpr std::string_view kShortLabel = "AS";
  static constexpr std::string_view kConventions = "Fresnel at <V,H>";
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"n", ParamKind::Scalar, {0.0, 1e8}, "Phong-like exponent n"},
      params::kEta,
  };
  static AshikhminShirley fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("ks"), p.scalar("n"), p.scalar("eta")};
  }

  Rgb kd{0.0}, ks{0.0};
  double n = 1.0, eta = 1.5;

  // The specular lobe ρ_s = (n+1)⟨N,H⟩ⁿ F / (8π⟨V,H⟩ max(⟨L,N⟩, ⟨V,N⟩)), ρ = Kd/π + Ks ρ_s; shape = {n, η}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr double kNStarts[] = {3.0, 10.0, 30.0, 100.0, 300.0, 1e3, 3e3, 1e4, 3e4, 1e5, 1e6};
  static constexpr ShapeParam kShape[] = {{"n", FitScale::Log, 1e-2, 1e8, kNStarts}, params::kFitEta};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp;
    if (g.h.cosVH <= 0.0) return T(0.0);
    const T cosN = exp(shape[0] * std::log1p(-g.h.oneMinusCosTheta));
    return (shape[0] + 1.0) * cosN * fresnelCookTorrance(g.h.cosVH, shape[1]) /
           (8.0 * kPi * g.h.cosVH * std::max(g.cosL, g.cosV));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, ks, {n, eta}); }

  // Sampling: cos θ_h = ξ^(1/(n+1)), i.e. 1 − cos θ_h = −expm1(ln ξ / (n+1)); pdf_h = (n+1)/(2π) cosⁿθ_h.
  double specularProbability() const {
    // Head-on lobe albedo ≈ Ks F(1): the (n+1)/(2π) cosⁿ lobe integrates to 1 over H's hemisphere.
    return lobeProbability(meanOf(ks) * fresnelAtNormalIncidence(eta), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const { return samplePowerCosineLobe(V, n, u, L); }
  double lobePdf(const Vec3& L, const Vec3& V) const { return powerCosineLobePdf(L, V, n); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
