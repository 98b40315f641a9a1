// The reference path tracer: one camera path at a time, in plain scalar code, with its own random numbers
// (reference_path.cpp). It is the oracle the wave (path_vertex.h) is tested against, so it shares none of
// the wave's machinery: no lanes, no sheets, no split draws, no stratified sampler, no resampling; only the
// scene, its lights and the BRDFs, which it asks one question at a time. `glossy render --reference`
// renders with it (RenderSettings::reference).
#pragma once

#include "renderer/integrator/path_tracer.h"

#include <cstdint>
#include <random>

namespace glossy {

// Independent uniform numbers in [0, 1) for one pixel's samples: a Mersenne Twister seeded from (seed,
// first sample, pixel), so a pixel's numbers do not depend on the thread that draws them.
class ReferenceRandom {
 public:
  ReferenceRandom(uint32_t seed, uint32_t firstSample, uint32_t x, uint32_t y) {
    std::seed_seq sequence{seed, firstSample, x, y, 0x7265666eu};  // the last word keeps it apart from other users
    engine_.seed(sequence);
  }
  double next() { return double(engine_() >> 11) * 0x1p-53; }
  Vec2 next2D() {
    const double u = next();
    return {u, next()};
  }

 private:
  std::mt19937_64 engine_;
};

// The radiance arriving along a camera ray: pbrt-v4's PathIntegrator::Li with one light sample and one BSDF
// sample per vertex, combined by the power heuristic, and Russian roulette. Non-finite results are the
// caller's to drop. Only context.scene, .settings and .lights are read.
Rgb referenceRadiance(const PathContext& context, Ray ray, ReferenceRandom& random);

}  // namespace glossy
