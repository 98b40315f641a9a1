// Directional albedo a(V) = ∫ ρ(L, V) cos θ_L dω_L for any viewing angle θ_V, by deterministic quadrature
// (materials/models/albedo.h does V = N only). The integral is taken over the half-vector H, where every
// model's lobe sits at H = N whatever V is: L = 2⟨V,H⟩H − V, dω_L = 4⟨V,H⟩ dω_H, and with x = 1 − cos θ_h,
// dω_H = dx dφ_h. L stays above the horizon exactly for φ_h in [−a(x), a(x)], a = acos(−cos θ_V cos 2θ_h /
// (sin θ_V sin 2θ_h)), all φ_h up to θ_h = 45° − θ_V/2 and none past 45° + θ_V/2; so the φ integral has
// no horizon cut inside it, and x is split at both angles and into panels that halve toward x = 0 (lobes
// to x ~ 1e-8 wide get as many nodes as broad ones) and toward the last angle. Gauss-Legendre on every
// panel, 16 nodes each way. Accuracy (tests/plot_test.cpp): a Lambertian's albedo to 1e-9 at every θ_V;
// albedoAtNormalIncidence's values at θ_V = 0 to 1e-5 relative for the published fits (the microfacet fits
// agree to a few 1e-6: their integrands have kinks that move both rules by that much with the node count);
// a brute-force 1500 × 3000 sum at θ_V = 40° and 70° to 2e-4 relative (the sum's own error). Against 40 nodes
// each way, alum-bronze's fits move by at most 3e-4 relative (at grazing θ_V) and its measured curve by 0.5 %
// (a table is a step function, which Gauss rules integrate slowly): far below what a plot shows.
#pragma once

#include "materials/core/types.h"

#include <functional>

namespace glossy::plot {

// The albedo of `rho` (a scalar ρ(L, V), e.g. one channel) for V = (sin θ_V, 0, cos θ_V), θ_V in radians,
// in [0, π/2). A non-finite ρ (an unmeasured bin) counts as 0.
double directionalAlbedo(const std::function<double(const Vec3& L, const Vec3& V)>& rho, double thetaV);

}  // namespace glossy::plot
