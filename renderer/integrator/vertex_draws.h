// What a vertex takes of the sampler. The sampler dimensions of a path: the camera's film position (one 2D
// draw), then at every vertex that reflects, VertexDraws's slots in their declared order. Vertex k always
// owns the same kDimensions dimensions, so each stays stratified across the pixel's samples. A dimension
// the vertex cannot use (the light choice when one light has all the power, roulette before rouletteDepth)
// is skipped, not computed: a value depends only on its dimension's index, so skipping gives every other
// dimension what drawing would.
//
// The first vertex of a camera path takes RenderSettings::lightSamples light samples, drawn from the pixel's
// pattern of spp × lightSamples points (CmjSampler::getSplit2D), and deeper vertices one: what the first
// vertex's light brings is most of the image, and its extra samples share the camera ray and the BSDF
// sample, while a whole extra path would trace both again.
#pragma once

#include "renderer/integrator/path_tracer.h"
#include "renderer/sampling/cmj_sampler.h"

namespace glossy {

// Paths traced together by the wave, and the most lanes a batch draw takes.
constexpr int kWaveSize = 128;

struct VertexDraws {
  // The draws in the sampler's order, declared once: drawVertices takes them in this order, and their
  // count is the dimensions a vertex owns.
  enum Slot { kLightChoice, kLight, kLobe, kBsdf, kRoulette, kDimensions };
  int lightSamples = 1;
  double lightChoice[kMaxLightSamples] = {};  // which light (LightSet::choose), per light sample
  Vec2 light[kMaxLightSamples] = {};          // where on it (Light::sample)
  double lobe = 0.0;         // which of the BRDF's lobes
  Vec2 bsdf{0.0};            // the direction in that lobe
  double roulette = 0.0;     // whether the path survives Russian roulette
};

// Which of the skippable draws a vertex at this depth uses, and its light samples.
struct DrawsUsed {
  bool lightChoice, roulette;
  int lightSamples;
  DrawsUsed(const PathContext& context, int depth)
      : lightChoice(context.lights.hasChoice()), roulette(depth >= context.settings.rouletteDepth),
        lightSamples(depth == 1 ? context.settings.lightSamples : 1) {}
};

// The draws of a vertex for samplers[lanes[k]], k < n, into out[lanes[k]] (lanes < kWaveSize), slot by
// slot, each a batch draw (cmj_sampler.h), which gives one sampler (n = 1, the reference) the values of
// its scalar draws. The light slots give
// split draws (as many as the sampler's pattern splits, which is RenderSettings::lightSamples) at the
// first vertex, one elsewhere.
inline void drawVertices(CmjSampler* samplers, const int* lanes, int n, DrawsUsed used, VertexDraws* out) {
  double x[kWaveSize];
  Vec2 xy[kWaveSize];
  const bool split = n > 0 && used.lightSamples > 1 && samplers[lanes[0]].splits() > 1;
  for (int k = 0; k < n; ++k) out[lanes[k]].lightSamples = split ? int(samplers[lanes[k]].splits()) : 1;
  for (int slot = 0; slot < VertexDraws::kDimensions; ++slot) {
    if ((slot == VertexDraws::kLightChoice && !used.lightChoice) || (slot == VertexDraws::kRoulette && !used.roulette)) {
      // Left as it was: the choice has one outcome (one light has all the power), roulette is not played.
      for (int k = 0; k < n; ++k) samplers[lanes[k]].skip(1);
    } else if (split && slot == VertexDraws::kLightChoice) {
      for (int k = 0; k < n; ++k) samplers[lanes[k]].getSplit1D(out[lanes[k]].lightChoice);
    } else if (split && slot == VertexDraws::kLight) {
      for (int k = 0; k < n; ++k) samplers[lanes[k]].getSplit2D(out[lanes[k]].light);
    } else {
      const bool is2D = slot == VertexDraws::kLight || slot == VertexDraws::kBsdf;
      if (is2D) CmjSampler::get2D(samplers, lanes, n, xy); else CmjSampler::get1D(samplers, lanes, n, x);
      for (int k = 0; k < n; ++k) {
        const int i = lanes[k];
        VertexDraws& d = out[i];
        switch (slot) {
          case VertexDraws::kLightChoice: d.lightChoice[0] = x[i]; break;
          case VertexDraws::kLight: d.light[0] = xy[i]; break;
          case VertexDraws::kLobe: d.lobe = x[i]; break;
          case VertexDraws::kBsdf: d.bsdf = xy[i]; break;
          default: d.roulette = x[i];
        }
      }
    }
  }
}

}  // namespace glossy
