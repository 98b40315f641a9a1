// How many light samples (and, at the end, BSDF samples) a camera path's first vertex takes: a function of
// the BRDF there, so that each of a sheet's panels gets its own. A light sample pays for itself where the
// BRDF's own samples find the light poorly: a broad lobe. On a lobe a few milliradians wide nearly all that
// a light sample could find is weighted to the BSDF sample by MIS, and each further light sample costs a
// shadow ray, a light lookup and a BRDF value for almost nothing. The count does not enter the estimator's
// expectation: MIS weighs the vertex's light samples and its BSDF samples by the counts actually taken (the
// power heuristic with sample counts, direct_light.h), so any function gives an unbiased image; this one
// chooses for the variance.
#pragma once

#include "materials/models/brdf.h"
#include "renderer/integrator/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

namespace glossy {

// The counts a vertex may take when at most `most`: 1, 2, 4, … below it, and `most`, as a set (bit k − 1:
// k samples). A sheet's object vertex draws the union of its panels' counts (vertex_draws.h), so few
// distinct counts keep that small: at most 1 + 2 + 4 + 8 draws.
inline uint32_t lightCountLevels(int most) {
  most = std::max(1, most);
  uint32_t levels = 1u << (most - 1);
  for (int k = 1; k < most; k *= 2) levels |= 1u << (k - 1);
  return levels;
}

// The share of the BRDF's reflected light that a vertex's light samples carry when lit evenly, one light
// sample (density cos θ / π, the environment as glossy samples it toward the surface, idealised) against
// one BSDF sample under the balance heuristic: ∫ ρ cos · p_L / (p_L + p_B) over ∫ ρ cos, from the BRDF's own
// samples on a fixed stratified grid at three view angles. 1/2 for a Lambertian BRDF, near 0 for a sharp
// lobe. Deterministic: the same BRDF gets the same share wherever it is rendered.
inline double lightCarriedShare(const Brdf& brdf) {
  constexpr int kGrid = 16;
  double carried = 0.0, total = 0.0;
  for (const double cosView : {0.9, 0.6, 0.3}) {
    const Vec3 wo(std::sqrt(1.0 - cosView * cosView), 0.0, cosView);
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        const double uLobe = (i * kGrid + j + 0.5) / (kGrid * kGrid);
        const BrdfSample s = sample(brdf, wo, uLobe, Vec2((i + 0.5) / kGrid, (j + 0.5) / kGrid));
        if (!s.valid() || s.L.z <= 0.0) continue;
        const double w = (s.weight.r + s.weight.g + s.weight.b) / 3.0;
        if (!std::isfinite(w) || w <= 0.0) continue;
        const double light = s.L.z / kPi;
        total += w;
        carried += w * light / (light + s.pdf);
      }
  }
  return total > 0.0 ? carried / total : 0.0;
}

// The light samples at a first vertex of this BRDF, at most `most`: the level of lightCountLevels nearest
// (in ratio) to most · (2 · share)³. A Lambertian BRDF takes `most`; a lobe whose light samples carry
// under about a fifth of its light takes one. The cube is fitted to measured efficiency (docs/
// performance.md): the light samples' noise falls faster than 1/K where their pattern stratifies them,
// which favours many on broad lobes (blue-rubber is most efficient at 8), while on a sharp or heavy-tailed
// lobe the BSDF sample's noise, which more light samples cannot reduce, dominates (aluminium: 1).
inline int lightSamplesFor(const Brdf& brdf, int most) {
  most = std::max(1, most);
  const double twice = 2.0 * lightCarriedShare(brdf);
  const double want = std::max(most * twice * twice * twice, 1e-9);
  int best = 1;
  for (int k = 1; k <= most; ++k)
    if ((lightCountLevels(most) >> (k - 1) & 1u) && std::abs(std::log(k / want)) < std::abs(std::log(best / want))) best = k;
  return best;
}

// The BSDF samples at a first vertex of this BRDF where its further samples are resampled (no surface
// emits, so only the chosen one is traced, path_vertex.h) or traced each: kMaxBsdfSamples or
// kTracedBsdfSamples where its light samples carry under a fifth of its light (a lobe that takes one light
// sample), else one. On such a lobe nearly all of a pixel's noise is the BSDF sample's: how much of the
// map's light its narrow lobe happens to catch (bench/direct_light_split.cpp, docs/performance.md), which
// more light samples cannot reduce. The samples of one split set share the camera ray, the light samples
// and the vertex, and only the first goes on as the path: a further one costs a BRDF sample and a light
// lookup, and a ray if traced, not a whole path. The counts are those measured most efficient each way.
// The count, like the light samples', only sets the variance: MIS weighs each sample by both counts.
constexpr int kTracedBsdfSamples = 8;
inline int bsdfSamplesFor(const Brdf& brdf, bool resampled) {
  return lightCarriedShare(brdf) < 0.2 ? (resampled ? kMaxBsdfSamples : kTracedBsdfSamples) : 1;
}

// The BSDF samples every object vertex of a sheet takes when the sheet chooses its spp (--target-error,
// --time): its panels must share one count to share their samples. kSheetBsdfSamples unless the light
// samples carry at least two fifths of every panel's light; on such broad lobes the further samples cost
// more than the noise they take away. Fewer than a render's kMaxBsdfSamples: each further sample is paid
// by every panel, and the count and the threshold are those that reached a --target-error soonest on the
// supplement's sheets (docs/sheets.md).
constexpr int kSheetBsdfSamples = 8;
inline int sheetBsdfSamples(std::span<const Brdf> panels) {
  for (const Brdf& brdf : panels)
    if (lightCarriedShare(brdf) < 0.4) return kSheetBsdfSamples;
  return 1;
}

static_assert(kTracedBsdfSamples <= kMaxBsdfSamples && kSheetBsdfSamples <= kMaxBsdfSamples);

}  // namespace glossy
