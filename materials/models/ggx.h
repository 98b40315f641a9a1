// Trowbridge-Reitz (GGX) microfacet model with height-correlated Smith masking  [Kd, Ks, α, η]
//   ρ = Kd/π + Ks · D(H) · G₂(L, V) · F(⟨V,H⟩; η) / (4 ⟨L,N⟩⟨V,N⟩)
//   D(H)  = α² / (π cos⁴θ_h (α² + tan²θ_h)²)                       (Trowbridge & Reitz 1975; Walter et al. 2007)
//   G₂    = 1 / (1 + Λ(L) + Λ(V)),   Λ(ω) = (√(1 + α² tan²θ_ω) − 1) / 2                         (Heitz 2014)
// Not one of Löw et al.'s models: the one Mitsuba 3, pbrt-v4, bbm and ALTA users reach for first, with the
// same Kd, Ks and Cook-Torrance Fresnel F(⟨V,H⟩; η) as the four, so that its fits sit beside theirs.
// D is normalised (∫ D cos θ_h dω_h = 1), so the 1/π the Löw et al. lobes carry in their denominators is in D.
// [choice] G₂ is height-correlated rather than separable G₁(L)·G₁(V): a facet low on the surface is likely
// both masked and shadowed, which the product counts twice, darkening grazing reflection; the correlated
// form is the more accurate one at the same cost (Heitz 2014), and pbrt-v4's. Sampling needs only G₁(V).
// Without cancellation: D = α² (1 + t)² / (π (α² + t)²) with t = tan²θ_h, Λ = α² t / (2 (1 + √(1 + α² t))).
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"
#include "materials/models/fresnel.h"
#include "materials/models/half_vector.h"
#include "materials/models/lobe_geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

struct Ggx {
  static constexpr std::string_view kName = "ggx";
  static constexpr std::string_view kLabel = "GGX";
  static constexpr std::string_view kConventions = "normalised D, height-correlated Smith G, Fresnel at <V,H>";
  // α down to 1e-4: the first θ_h bin of a MERL table is 1.9e-4 rad wide, so no measurement tells a sharper
  // lobe from a mirror; up to 10, as Cook-Torrance's m, far rougher than any measured surface.
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"alpha", ParamKind::Scalar, {1e-4, 10.0}, "GGX roughness α"},
      params::kEta,
  };
  static Ggx fromParams(const ParamSet& p) { return {p.rgb("kd"), p.rgb("ks"), p.scalar("alpha"), p.scalar("eta")}; }

  Rgb kd{0.0}, ks{0.0};
  double alpha = 0.1, eta = 1.5;

  // ρ = Kd/π + Ks ρ_s, the specular lobe ρ_s = D G₂ F / (4⟨L,N⟩⟨V,N⟩); shape = {α, η}.
  static constexpr std::string_view kScaleKey = "ks";
  static constexpr double kAlphaStarts[] = {0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8};
  static constexpr ShapeParam kShape[] = {{"alpha", FitScale::Log, 1e-4, 10.0, kAlphaStarts}, params::kFitEta};
  template <class T>
  T lobe(const LobeGeometry& g, const T* shape) const {
    const T a2 = shape[0] * shape[0];
    const T g2 = 1.0 / (1.0 + lambda(a2, g.cosL) + lambda(a2, g.cosV));
    return distribution(a2, g.h.tan2Theta) * g2 * fresnelCookTorrance(g.h.cosVH, shape[1]) / (4.0 * g.cosL * g.cosV);
  }
  // D at tan²θ_h = t.
  template <class T>
  static T distribution(const T& a2, double t) {
    return a2 * ((1.0 + t) * (1.0 + t)) / (kPi * (a2 + t) * (a2 + t));
  }
  // Smith's Λ of a direction with cos θ = c > 0.
  template <class T>
  static T lambda(const T& a2, double c) {
    using std::sqrt;
    const T x = a2 * ((1.0 - c) * (1.0 + c) / (c * c));
    return x / (2.0 * (1.0 + sqrt(1.0 + x)));
  }

  Rgb eval(const Vec3& L, const Vec3& V) const { return evalLobeModel(*this, L, V, kd, ks, {alpha, eta}); }

  // Sampling: H from the visible normals seen from V (Heitz 2018), pdf_H = G₁(V) ⟨V,H⟩ D(H) / ⟨V,N⟩, so
  // pdf_L = pdf_H / (4⟨V,H⟩) = D(H) / (4 (1 + Λ(V)) ⟨V,N⟩).
  double specularProbability() const {
    // Head-on lobe albedo ≈ Ks F(1): D cos θ_h integrates to 1 (G₂ ≈ 1).
    return lobeProbability(meanOf(ks) * fresnelAtNormalIncidence(eta), kd);
  }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const {
    // V stretched to the configuration of α = 1, where the visible normals are a projected hemisphere: a
    // uniform point of the disk, pushed toward V's side in proportion to the half disk V hides, lifted to it.
    const Vec3 v = glm::normalize(Vec3(alpha * V.x, alpha * V.y, V.z));
    const double len2 = v.x * v.x + v.y * v.y;
    const Vec3 t1 = len2 > 0.0 ? Vec3(-v.y, v.x, 0.0) / std::sqrt(len2) : Vec3(1.0, 0.0, 0.0);
    const Vec3 t2 = glm::cross(v, t1);
    const Vec2 p = squareToConcentricDisk(u);
    const double s = 0.5 * (1.0 + v.z);
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p.x * p.x)) + s * p.y;
    const Vec3 n = p.x * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p.x * p.x - p2 * p2)) * v;
    // Unstretched, it is H.
    const Vec3 h = glm::normalize(Vec3(alpha * n.x, alpha * n.y, std::max(0.0, n.z)));
    const double vh = glm::dot(V, h);
    if (!(vh > 0.0)) return false;
    L = 2.0 * vh * h - V;
    return true;
  }
  double lobePdf(const Vec3& L, const Vec3& V) const {
    const double a2 = alpha * alpha;
    return distribution(a2, HalfVector(L, V).tan2Theta) / (4.0 * (1.0 + lambda(a2, V.z)) * V.z);
  }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
