// What a BRDF's sample() returns, and the cosine-lobe sampler every model uses until it samples its own
// lobe (lobe sampling is issue #4; until then the pdf is exactly cos θ_L / π, never an approximation).
#pragma once

#include "materials/core/types.h"
#include "materials/models/warp.h"

namespace glossy {

struct BrdfSample {
  Vec3 L{0.0};      // sampled direction toward the light, local frame
  double pdf = 0.0; // solid-angle density of L; 0 marks an invalid sample
  Rgb weight{0.0};  // ρ(L,V) cos θ_L / pdf
  bool valid() const { return pdf > 0.0; }
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

}  // namespace glossy
