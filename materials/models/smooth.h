// Smooth Surface model (Löw et al. 2012, eq. 1)  [Kd, A, B, C, η]
//   ρ = Kd/π + A · F(cos θ_d; η) · (1 + B‖D_P‖²)^(−C)
//   D_P = L_p + V_p  (projected deviation from the mirror direction; ‖D_P‖² = |h_p|² with h = L + V)
//   [convention] cos θ_d = sqrt(1 − ¼‖L_p − V_p‖²), the projected difference angle (fresnel = "projected");
//                fresnel = "vh" uses ⟨V,H⟩ instead. No π and no cosine factors on the specular term (G' = 1).
#pragma once

#include "materials/models/abc_profile.h"
#include "materials/models/brdf_sample.h"
#include "materials/models/fresnel.h"
#include "materials/models/lobe_geometry.h"
#include "materials/models/common_params.h"

#include <algorithm>
#include <cmath>

namespace glossy {

struct Smooth {
  static constexpr std::string_view kName = "smooth";
  static constexpr std::string_view kLabel = "Smooth Surface";
  static constexpr std::string_view kShortLabel = "Smooth";
  static constexpr std::string_view kConventions = "Fresnel at the projected cos theta_d unless smoothFresnel = vh";
  static constexpr std::string_view kFresnelChoices[] = {"projected", "vh"};
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kAbcA, params::kAbcB, params::kAbcC,
      params::kEta,
      {"fresnel", ParamKind::Choice, {}, "cos θ_d of the Fresnel factor: projected (default) or vh",
       kFresnelChoices, true},
  };
  static Smooth fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("a"), p.scalar("b"), p.scalar("c"), p.scalar("eta"),
            p.choice("fresnel", kParams) == "vh"};
  }

  Rgb kd{0.0}, a{0.0};
  double b = 0.0, c = 1.0, eta = 1.5;
  bool fresnelVH = false;

  // The specular lobe ρ_s = F(cos θ_d; η) (1 + B‖D_P‖²)^(−C), so that ρ = Kd/π + A ρ_s; shape = {B, C, η}.
  static constexpr std::string_view kScaleKey = "a";
  static constexpr ShapeParam kShape[] = {params::kFitAbcB, params::kFitAbcC, params::kFitEta};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    using std::exp, std::log1p;
    const double cosThetaD = fresnelVH ? g.h.cosVH : std::sqrt(std::max(0.0, 1.0 - 0.25 * g.dm2));
    return fresnelCookTorrance(cosThetaD, shape[2]) * exp(-shape[1] * log1p(shape[0] * g.dp2));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, a, {b, c, eta}); }

  // Sampling: the projected point L_p on the unit disk with density ∝ (1 + B|L_p − r_p|²)^(−C), r_p = −V_p:
  // d² = |L_p − r_p|² from the ABC profile on [0, (1 + |V_p|)²], the angle uniform, |L_p| ≥ 1 rejected;
  // pdf(L) = p_disk(L_p) cos θ_L with p_disk = S(d²) / (π ∫₀^{R²} S). Exact for every C.
  double specularProbability() const {
    // Head-on lobe albedo ≈ π A F(1) ∫₀¹ S(s) ds (s = sin²θ_L).
    return lobeProbability(kPi * meanOf(a) * fresnelAtNormalIncidence(eta) * AbcProfile{b, c}.integral(1.0), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const {
    const double r = 1.0 + std::sqrt(V.x * V.x + V.y * V.y);
    const double d = std::sqrt(AbcProfile{b, c}.invert(u.x, r * r)), psi = 2.0 * kPi * u.y;
    const double lx = -V.x + d * std::cos(psi), ly = -V.y + d * std::sin(psi);
    const double r2 = lx * lx + ly * ly;
    if (r2 >= 1.0) return false;
    L = Vec3(lx, ly, std::sqrt(1.0 - r2));
    return true;
  }
  double lobePdf(const Vec3& L, const Vec3& V) const {
    const double r = 1.0 + std::sqrt(V.x * V.x + V.y * V.y);
    const double dx = L.x + V.x, dy = L.y + V.y;
    const AbcProfile s{b, c};
    return s(dx * dx + dy * dy) / (kPi * s.integral(r * r)) * L.z;
  }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
