// Measured BRDF: a MERL table with the reference nearest-bin lookup (shared/spec/merl.md).
//   ρ(L, V) = table[bin(θ_h, θ_d, φ_d)] × channel scale,  0 in unmeasured bins and below the horizon.
//
// Sampling: a one-sample mixture of
//   - the tabulated half-vector density built from the table (materials/models/merl_sampling.h), weight 1 − c − q,
//   - the cosine lobe, weight c (everything the table's proposal might miss stays reachable),
//   - optionally an analytic proposal (e.g. the material's best-fitting lobe), weight q.
//   pdf(L) = (1 − c − q) p_table(L) + c cos θ_L / π + q p_fit(L).
// The defaults (c = 0.1, q = 0) were chosen by measurement: docs/sampling.md, "Measured data".
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/models/brdf_model.h"
#include "materials/models/merl_sampling.h"

#include <memory>

namespace glossy {

struct Measured {
  static constexpr std::string_view kName = "measured";
  static constexpr std::string_view kLabel = "Measured";
  static constexpr double kDefaultCosineWeight = 0.1;

  std::shared_ptr<const MerlTable> table;
  std::shared_ptr<const MerlSampling> sampling;  // null: no tabulated proposal
  std::shared_ptr<const BrdfModel> proposal;  // a further sampler, with its exact pdf (withProposal()); null: none
  double cosineWeight = 1.0, proposalWeight = 0.0;

  Measured() = default;
  // The table with its tabulated sampler (built here, from the table) and the default cosine share.
  explicit Measured(std::shared_ptr<const MerlTable> t);
  // For comparisons: cosine sampling alone.
  static Measured cosineOnly(std::shared_ptr<const MerlTable> t);

  Rgb eval(const Vec3& L, const Vec3& V) const { return table->eval(L, V); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const;
  double pdf(const Vec3& L, const Vec3& V) const;
};

}  // namespace glossy
