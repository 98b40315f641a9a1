// What a BRDF's sample() returns; the cosine-lobe sampler (Lambertian, and measured data until it gets its
// own); and the one-sample mixture every analytic model uses: its specular lobe with probability
// pSpecular, the cosine lobe otherwise.
#pragma once

#include "materials/core/lane_math.h"
#include "materials/core/types.h"
#include "materials/models/half_vector.h"
#include "materials/models/warp.h"

#include <algorithm>
#include <cmath>

namespace glossy {

struct BrdfSample {
  Vec3 L{0.0};      // sampled direction toward the light, local frame
  double pdf = 0.0; // solid-angle density of L; 0 marks an invalid sample
  Rgb weight{0.0};  // ρ(L,V) cos θ_L / pdf
  bool valid() const { return pdf > 0.0; }
};

// ρ(L, V) and the sampling density at L together: where both are needed (a light sample's MIS weight, a
// BSDF sample's weight) a model computes what they share once.
struct BrdfValue {
  Rgb f{0.0};
  double pdf = 0.0;
};

template <class Model>
BrdfSample sampleCosineLobe(const Model& model, const Vec3& V, Vec2 u) {
  BrdfSample s;
  if (V.z <= 0.0) return s;
  s.L = squareToCosineHemisphere(u);
  s.pdf = cosineHemispherePdf(s.L);
  if (s.pdf <= 0.0) return BrdfSample{};
  // ρ cos/pdf = ρ π: no division, so no blow-up near the horizon.
  s.weight = model.eval(s.L, V) * kPi;
  return s;
}

// Probability of sampling the specular lobe, from the lobes' approximate albedos (the diffuse one is the
// mean of Kd). Each lobe keeps some probability unless its albedo is zero, so MIS always has both.
inline double meanOf(const Rgb& c) { return (c.r + c.g + c.b) / 3.0; }

inline double lobeProbability(double specularAlbedo, const Rgb& kd) {
  const double diffuse = meanOf(kd);
  if (!(specularAlbedo > 0.0)) return 0.0;
  if (!(diffuse > 0.0)) return 1.0;
  const double p = specularAlbedo / (specularAlbedo + diffuse);
  return p < 0.05 ? 0.05 : p > 0.95 ? 0.95 : p;
}

// The mixture's density from its specular lobe's density at L (for L.z > 0).
inline double mixtureDensity(double pSpecular, double lobePdf, const Vec3& L) {
  return (pSpecular > 0.0 ? pSpecular * lobePdf : 0.0) + (pSpecular < 1.0 ? (1.0 - pSpecular) * L.z * kInvPi : 0.0);
}

template <class Model>
double mixturePdf(const Model& model, const Vec3& L, const Vec3& V) {
  if (V.z <= 0.0 || L.z <= 0.0) return 0.0;
  const double p = model.specularProbability();
  return mixtureDensity(p, p > 0.0 ? model.lobePdf(L, V) : 0.0, L);
}

// A model's evalPdf(L, V) where it has one, else eval and pdf separately (same values either way).
template <class Model>
BrdfValue evalWithPdf(const Model& model, const Vec3& L, const Vec3& V) {
  if constexpr (requires { model.evalPdf(L, V); })
    return model.evalPdf(L, V);
  else
    return {model.eval(L, V), model.pdf(L, V)};
}

// The sample at direction L (L_z > 0) with the BRDF's value and density there: invalid where the density
// is not a positive finite number.
inline BrdfSample mixtureSample(const Vec3& L, const BrdfValue& value) {
  if (!(value.pdf > 0.0) || !std::isfinite(value.pdf)) return {};
  return {L, value.pdf, value.f * (L.z / value.pdf)};
}

// The mixture sampler. Model provides eval(L, V), specularProbability(), sampleLobe(V, u, L) (false when
// the lobe gives no direction) and lobePdf(L, V) (solid angle, exactly what sampleLobe draws from).
// A direction below the horizon is an invalid sample; the pdf is not renormalised for it.
template <class Model>
BrdfSample sampleMixture(const Model& model, const Vec3& V, double uLobe, Vec2 u) {
  if (V.z <= 0.0) return {};
  BrdfSample s;
  if (uLobe < model.specularProbability()) {
    if (!model.sampleLobe(V, u, s.L)) return {};
  } else {
    s.L = squareToCosineHemisphere(u);
  }
  if (s.L.z <= 0.0) return {};
  return mixtureSample(s.L, evalWithPdf(model, s.L, V));
}

// The half-vector warp every microfacet-style sampler shares: H from (1 − cos θ_h, φ), L = reflect(V, H).
// False when L would face away from H's side of V.
inline bool reflectAboutHalfVector(const Vec3& V, double oneMinusCos, double cosPhi, double sinPhi, Vec3& L) {
  const double cosTheta = 1.0 - oneMinusCos;
  const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
  const Vec3 H(sinTheta * cosPhi, sinTheta * sinPhi, cosTheta);
  const double vh = V.x * H.x + V.y * H.y + V.z * H.z;
  if (vh <= 0.0) return false;
  L = 2.0 * vh * H - V;
  return true;
}
inline bool reflectAboutHalfVector(const Vec3& V, double oneMinusCos, double phi, Vec3& L) {
  return reflectAboutHalfVector(V, oneMinusCos, std::cos(phi), std::sin(phi), L);
}

// The power-cosine half-vector lobe (Ashikhmin-Shirley's sampler, which Blinn-Phong's cosⁿθ_h shares):
// cos θ_h = ξ^(1/(n+1)), i.e. 1 − cos θ_h = −expm1(ln ξ / (n+1)), φ uniform; pdf_h = (n+1)/(2π) cosⁿθ_h,
// and over L, pdf_h / (4⟨V,H⟩).
inline bool samplePowerCosineLobe(const Vec3& V, double n, Vec2 u, Vec3& L) {
  return reflectAboutHalfVector(V, -std::expm1(std::log(u.x) / (n + 1.0)), 2.0 * kPi * u.y, L);
}
inline double powerCosineLobePdf(const Vec3& L, const Vec3& V, double n) {
  const HalfVector h(L, V);
  if (h.cosVH <= 0.0) return 0.0;
  return (n + 1.0) / (2.0 * kPi) * std::exp(n * std::log1p(-h.oneMinusCosTheta)) / (4.0 * h.cosVH);
}

// Batch forms, for the path tracer's waves: a model that computes its lobe's transcendental functions for
// many lanes at once (lanes::, libmvec) provides
//   void lobeOneMinusCosBatch(const Vec2* u, const bool* lobe, double* out, int n)
//       out[k] = 1 − cos θ_h of sampleLobe's half vector for u[k], where lobe[k] (others: anything finite)
//   void evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n)    out[k] = evalPdf(L[k], V[k])
// and sampleMixtureBatch then draws what sampleMixture draws, lane by lane (up to the last bits of the
// vector math). n ≤ kMaxBatchLanes. A lane's result never depends on the other lanes.
inline constexpr int kMaxBatchLanes = 128;

template <class Model>
concept HasBatchForms = requires(const Model& m, const Vec2* u, const bool* b, double* d, const Vec3* v, BrdfValue* o) {
  m.lobeOneMinusCosBatch(u, b, d, 0);
  m.evalPdfBatch(v, v, o, 0);
};

// The mixture sampler of sampleMixture, for n lanes at once.
template <class Model>
void sampleMixtureBatch(const Model& model, const Vec3* V, const double* uLobe, const Vec2* u, BrdfSample* out,
                        int n) {
  const double p = model.specularProbability();
  bool lobe[kMaxBatchLanes] = {}, ok[kMaxBatchLanes];
  double oneMinusCos[kMaxBatchLanes], r[kMaxBatchLanes], phi[kMaxBatchLanes], s[kMaxBatchLanes], c[kMaxBatchLanes];
  for (int k = 0; k < n; ++k) lobe[k] = uLobe[k] < p;
  model.lobeOneMinusCosBatch(u, lobe, oneMinusCos, n);
  // φ of the half vector, or the concentric disk's polar point for the cosine lobe: one sin/cos pass for both.
  for (int k = 0; k < n; ++k) {
    if (lobe[k]) {
      phi[k] = 2.0 * kPi * u[k].y;
      r[k] = 0.0;
    } else {
      squareToConcentricDiskPolar(u[k], r[k], phi[k]);
    }
  }
  lanes::sinCos(phi, s, c, n);
  Vec3 L[kMaxBatchLanes];
  for (int k = 0; k < n; ++k) {
    if (lobe[k]) {
      ok[k] = V[k].z > 0.0 && reflectAboutHalfVector(V[k], oneMinusCos[k], c[k], s[k], L[k]);
    } else {
      ok[k] = V[k].z > 0.0;
      L[k] = diskToCosineHemisphere({r[k] * c[k], r[k] * s[k]});
    }
    ok[k] = ok[k] && L[k].z > 0.0;
    if (!ok[k]) L[k] = Vec3(0.0);  // evalPdfBatch answers {} for it
  }
  BrdfValue value[kMaxBatchLanes];
  model.evalPdfBatch(L, V, value, n);
  for (int k = 0; k < n; ++k) out[k] = ok[k] ? mixtureSample(L[k], value[k]) : BrdfSample{};
}

}  // namespace glossy
