// Importance sampling of a measured BRDF, built once per material from the table itself.
//
// The proposal lives in half-vector space, where a measured lobe keeps its shape as the view moves: for
// each of kViewBins view elevations θ_v a 2D piecewise-constant density over H, with cells that are the
// table's own 90 θ_h bins (θ_h = (i/90)² π/2: fine where glossy peaks are) × kPhiBins in φ_h − φ_v. A cell's
// weight is its integral of ρ̄(L, V) cos θ_L · 4⟨V,H⟩ (ρ̄: mean of R, G, B; 4⟨V,H⟩ = dω_L/dω_H) at the bin's
// centre view, estimated from 2 × 2 points; within a cell H is uniform in solid angle. L = reflect(V, H).
// Between two view elevations the two densities are mixed linearly (one is picked at random), so the
// density is continuous in V and still exact:
//   pdf_H(H | V) = (1 − t) p_k(H) + t p_{k+1}(H),   pdf(L | V) = pdf_H / (4⟨V,H⟩).
// A reflected L below the horizon is a rejected sample; the density is not renormalised for it.
#pragma once

#include "materials/core/types.h"
#include "materials/sampling/distribution.h"

#include <array>
#include <vector>

namespace glossy {

class MerlTable;

class MerlSampling {
 public:
  static constexpr int kViewBins = 32;  // θ_v in [0, π/2], centres at (k + ½) π/64
  static constexpr int kThetaBins = 90; // the table's θ_h bins
  static constexpr int kPhiBins = 64;   // φ_h − φ_v in [−π, π)

  explicit MerlSampling(const MerlTable& table);

  // H from the density for V (V.z > 0), uChoice picking between the two nearest view elevations; then
  // L = reflect(V, H). False when ⟨V,H⟩ ≤ 0 or L is below the horizon.
  bool sample(const Vec3& V, double uChoice, Vec2 u, Vec3& L) const;
  // The solid-angle density of L that sample() draws from (0 below the horizon).
  double pdf(const Vec3& L, const Vec3& V) const;

  size_t bytes() const;  // memory held by the tables

 private:
  struct ViewPosition {
    int k0, k1;
    double t;  // weight of k1
  };
  static ViewPosition viewPosition(const Vec3& V);

  std::array<double, kThetaBins + 1> xEdges_;  // 1 − cos θ_h at the θ_h bin edges
  std::vector<Distribution2D> views_;           // kViewBins densities over (φ, θ_h) ∈ [0,1)²
};

}  // namespace glossy
