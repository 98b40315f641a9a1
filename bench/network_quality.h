// How far a Neural BRDF's network is from being a plausible BRDF, from the network alone (the measurement it
// was fitted to is not at hand): the figures of docs/measured.md, "Data quality", which bench/nbrdf_quality
// prints for each .nbrdf.
//
// The network is evaluated as tabulate() does (materials/nbrdf/neural_brdf.h): at each measured bin's lower
// edges, at φ_d = k° and k° + 180°, with evalAngles. Swapping L and V turns φ_d into φ_d + 180°, so a
// reciprocal BRDF has the same value at both; tabulate() keeps their mean ρ̄, clamped at 0.
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/nbrdf/neural_brdf.h"

#include <array>
#include <cstddef>

namespace glossy::bench {

struct NetworkQuality {
  static constexpr double kAsymmetryFloor = 0.01;  // 1/sr: below it a bin's relative asymmetry is not counted
  static constexpr int kAlbedoAngles = 18;          // θ_V = 0°, 5°, …, 85°

  size_t measuredBins = 0;
  std::array<size_t, 3> negativeBins{};  // per channel: bins whose ρ̄ < 0 (tabulated as 0)
  std::array<double, 3> lowest{};        // per channel: the least ρ̄ (1/sr), 0 when none is negative
  size_t nonFiniteBins = 0;              // bins with a non-finite value at either φ_d
  // Non-reciprocity, over the measured bins and channels, a and b the values at φ_d and φ_d + 180°:
  double asymmetryRms = 0.0;  // sqrt(Σ (a − b)²) / sqrt(Σ ρ̄²)
  double asymmetryMax = 0.0;  // the largest |a − b| / ρ̄ where ρ̄ ≥ kAsymmetryFloor
  // The tabulated table's directional albedo a(θ_V) = ∫ ρ cos θ_L dω_L (renderer/plot/directional_albedo.h)
  // at θ_V = 5° k: its largest value over the channels and angles, and where.
  double maxAlbedo = 0.0;
  int maxAlbedoChannel = 0;
  double maxAlbedoThetaVDeg = 0.0;

  double negativeShare(int c) const { return measuredBins ? double(negativeBins[size_t(c)]) / double(measuredBins) : 0.0; }
};

// The figures of `network`, whose tabulate() is `table`. Uses all cores.
NetworkQuality assessNetwork(const NeuralBrdf& network, const MerlTable& table);

}  // namespace glossy::bench
