// Lafortune, one isotropic lobe, with Ngan, Durand & Matusik 2005's normalisation  [Kd, Ks, Cxy, Cz, n]
//   ρ = Kd/π + Ks · (n+2)/(2π) · [max(s, 0) / max(|Cxy|, |Cz|)]ⁿ,   s = Cxy (L_x V_x + L_y V_y) + Cz L_z V_z
// Lafortune et al. 1997's lobe, L and V both pointing away from the surface: Cxy < 0 < Cz gives a lobe about
// the mirror direction (every published fit has Cxy ∈ [−0.707, −0.577], Cz ∈ [1.2e-10, 0.577]); with
// |Cxy| = |Cz| its peak is Ks (n+2)/(2π), as the normalised Phong's. bbm's `NganLafortune` (bsdfmodel/ngan.h,
// commit 9807fb38) computes the same as max(s,0)ⁿ · (n+2)/(2π) / max(Cz², Cxy²)^(n/2), whose two powers
// underflow to 0·∞ = NaN for n ≳ 1240 (33 of the 86 fits); [choice] the ratio is taken before the power, which
// agrees with bbm to 6e-12 wherever bbm is finite. s ≤ |C∘V| ≤ max(|Cxy|, |Cz|), so the ratio is at most 1.
// [convention] Kd is the fit's Lambertian albedo, ρ carries no cos θ_L; ρ = 0 unless L_z > 0 and V_z > 0.
#pragma once

#include "materials/core/frame.h"
#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

struct Lafortune {
  static constexpr std::string_view kName = "lafortune";
  static constexpr std::string_view kLabel = "Lafortune";
  static constexpr std::string_view kConventions = "Ngan 2005: one lobe, (n+2)/(2 pi) [s/max|C|]^n";
  // Cz from 1e-12, not 0: with Cxy = Cz = 0 the normalisation is 0/0; the published Cz go down to 1.2e-10.
  // Coefficients up to 10 in size (the published ones are below 1: only their ratio and n shape the lobe).
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"cxy", ParamKind::Scalar, {-10.0, 10.0}, "Lafortune coefficient Cx = Cy (negative: forward scattering)"},
      {"cz", ParamKind::Scalar, {1e-12, 10.0}, "Lafortune coefficient Cz"},
      {"n", ParamKind::Scalar, {0.0, 1e8}, "Lafortune exponent n"},
  };
  static Lafortune fromParams(const ParamSet& p) {
    return {p.rgb("kd"), p.rgb("ks"), p.scalar("cxy"), p.scalar("cz"), p.scalar("n")};
  }

  Rgb kd{0.0}, ks{0.0};
  double cxy = -0.577, cz = 0.577, n = 1.0;

  Rgb eval(const Vec3& L, const Vec3& V) const {
    if (L.z <= 0.0 || V.z <= 0.0) return Rgb(0.0);
    const double s = cxy * (L.x * V.x + L.y * V.y) + cz * L.z * V.z;
    if (!(s > 0.0)) return kd * kInvPi;
    const double ratio = std::min(1.0, s / std::max(std::abs(cxy), std::abs(cz)));
    return kd * kInvPi + ks * ((n + 2.0) / (2.0 * kPi) * std::exp(n * std::log(ratio)));
  }

  // Sampling: a cosⁿ lobe about the axis a = C∘V / |C∘V| (Lafortune's own, bbm's), cos θ_a = ξ^(1/(n+1)) in the
  // hemisphere about a, pdf = (n+1)/(2π) max(⟨a,L⟩, 0)ⁿ; directions below the horizon are rejected, not
  // renormalised. No fitter lobe (kShape): Cxy is signed, and the fitter's scales are for positive parameters.
  double specularProbability() const {
    // The lobe's albedo is about Ks (|C∘V| / max|C|)ⁿ, Ks where the view is aligned with the larger coefficient:
    // that peak, so that a lobe dark head-on (Cz ≪ |Cxy|) still gets samples at grazing views.
    return lobeProbability(meanOf(ks), kd);
  }
  bool axis(const Vec3& V, Vec3& a) const {
    const Vec3 c(cxy * V.x, cxy * V.y, cz * V.z);
    const double len = glm::length(c);
    if (!(len > 0.0)) return false;
    a = c / len;
    return true;
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const {
    Vec3 a;
    if (!axis(V, a)) return false;
    const double x = -std::expm1(std::log(u.x) / (n + 1.0));  // 1 − cos θ_a, without cancellation
    const double sinTheta = std::sqrt(std::max(0.0, x * (2.0 - x))), phi = 2.0 * kPi * u.y;
    L = Frame(a).toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), 1.0 - x));
    return true;
  }
  double lobePdf(const Vec3& L, const Vec3& V) const {
    Vec3 a;
    if (!axis(V, a)) return 0.0;
    const Vec3 d = a - L;
    const double x = 0.5 * glm::dot(d, d);  // 1 − ⟨a,L⟩ for unit a and L
    if (!(x < 1.0)) return 0.0;
    return (n + 1.0) / (2.0 * kPi) * std::exp(n * std::log1p(-x));
  }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
