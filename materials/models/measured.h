// Measured BRDF: a MERL table with the reference nearest-bin lookup (shared/spec/merl.md).
//   ρ(L, V) = table[bin(θ_h, θ_d, φ_d)] × channel scale,  0 in unmeasured bins and below the horizon.
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/models/brdf_sample.h"

#include <memory>

namespace glossy {

struct Measured {
  static constexpr std::string_view kName = "measured";
  static constexpr std::string_view kLabel = "Measured";

  std::shared_ptr<const MerlTable> table;

  Rgb eval(const Vec3& L, const Vec3& V) const { return table->eval(L, V); }
  BrdfSample sample(const Vec3& V, double /*uLobe*/, Vec2 u) const { return sampleCosineLobe(*this, V, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return V.z > 0.0 ? cosineHemispherePdf(L) : 0.0; }
};

}  // namespace glossy
