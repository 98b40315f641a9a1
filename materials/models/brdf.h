// A BRDF of any kind, by value. A closed variant rather than a virtual base: the integrator's hot path
// dispatches with a switch, nothing is allocated per material, and a new model is one more alternative.
//
// Every model M provides, in the local shading frame (N = +z, L toward the light, V toward the viewer):
//   Rgb M::eval(L, V)                       ρ(L, V), 0 unless L_z > 0 and V_z > 0
//   BrdfSample M::sample(V, uLobe, u)       a direction L drawn from M's sampling density given V
//   double M::pdf(L, V)                     exactly that density, in solid angle
//   BrdfValue M::evalPdf(L, V)              optional: both at once, where they share work
//   lobeOneMinusCosBatch, evalPdfBatch      optional: batch forms for the path tracer (brdf_sample.h)
#pragma once

#include "materials/models/ashikhmin_shirley.h"
#include "materials/models/cook_torrance.h"
#include "materials/models/lambertian.h"
#include "materials/models/measured.h"
#include "materials/models/microfacet.h"
#include "materials/models/smooth.h"

#include <algorithm>
#include <memory>
#include <type_traits>
#include <variant>

namespace glossy {

using Brdf = std::variant<Lambertian, Smooth, Microfacet, CookTorrance, AshikhminShirley, Measured>;

inline Rgb eval(const Brdf& brdf, const Vec3& L, const Vec3& V) {
  return std::visit([&](const auto& m) { return m.eval(L, V); }, brdf);
}
inline BrdfSample sample(const Brdf& brdf, const Vec3& V, double uLobe, Vec2 u) {
  return std::visit([&](const auto& m) { return m.sample(V, uLobe, u); }, brdf);
}
inline double pdf(const Brdf& brdf, const Vec3& L, const Vec3& V) {
  return std::visit([&](const auto& m) { return m.pdf(L, V); }, brdf);
}
// {eval, pdf} at once, for the models that share work between the two (the same values).
inline BrdfValue evalPdf(const Brdf& brdf, const Vec3& L, const Vec3& V) {
  return std::visit([&](const auto& m) { return evalWithPdf(m, L, V); }, brdf);
}

// A wave's BSDF samples and BRDF values: out[k] = sample(brdf, V[k], uLobe[k], u[k]), and
// evalPdf(brdf, L[k], V[k]), for k < n. Models with batch forms (brdf_sample.h) compute their
// transcendental functions for kMaxBatchLanes lanes at a time; the others are called lane by lane.
inline void sampleBatch(const Brdf& brdf, const Vec3* V, const double* uLobe, const Vec2* u, BrdfSample* out, int n) {
  std::visit(
      [&](const auto& m) {
        if constexpr (HasBatchForms<std::decay_t<decltype(m)>>) {
          for (int first = 0; first < n; first += kMaxBatchLanes)
            sampleMixtureBatch(m, V + first, uLobe + first, u + first, out + first, std::min(kMaxBatchLanes, n - first));
        } else {
          for (int k = 0; k < n; ++k) out[k] = m.sample(V[k], uLobe[k], u[k]);
        }
      },
      brdf);
}
inline void evalPdfBatch(const Brdf& brdf, const Vec3* L, const Vec3* V, BrdfValue* out, int n) {
  std::visit(
      [&](const auto& m) {
        if constexpr (HasBatchForms<std::decay_t<decltype(m)>>) {
          for (int first = 0; first < n; first += kMaxBatchLanes)
            m.evalPdfBatch(L + first, V + first, out + first, std::min(kMaxBatchLanes, n - first));
        } else {
          for (int k = 0; k < n; ++k) out[k] = evalWithPdf(m, L[k], V[k]);
        }
      },
      brdf);
}

// A measured BRDF that also proposes directions from an analytic lobe (its fit), with mixture weight q.
inline Measured withProposal(Measured m, Brdf lobe, double q) {
  auto shared = std::make_shared<const Brdf>(std::move(lobe));
  m.proposal = std::make_shared<const MeasuredProposal>(MeasuredProposal{
      [shared](const Vec3& V, double uLobe, Vec2 u) { return sample(*shared, V, uLobe, u); },
      [shared](const Vec3& L, const Vec3& V) { return pdf(*shared, L, V); }});
  m.proposalWeight = q;
  return m;
}

}  // namespace glossy
