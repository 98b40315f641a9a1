// Directional albedo by deterministic quadrature, for checks and for the library listing.
#pragma once

#include "materials/models/brdf.h"

namespace glossy {

// a(N) = ∫ ρ(L, N) cos θ_L dω_L, the albedo seen head-on. At V = N an isotropic BRDF depends on θ_L only,
// so this is the 1D integral 2π ∫₀¹ ρ(x) (1 − x) dx over x = 1 − cos θ_L, done with Gauss-Legendre on
// panels that halve toward x = 0: lobes down to x ~ 1e-8 wide (B = 8.1e6) get as many nodes as broad ones.
Rgb albedoAtNormalIncidence(const Brdf& brdf);

}  // namespace glossy
