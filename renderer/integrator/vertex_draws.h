// What a vertex takes of the sampler. The sampler dimensions of a path: the camera's film position (one 2D
// draw), then at every vertex that reflects, VertexDraws's slots in their declared order. Vertex k always
// owns the same kDimensions dimensions, so each stays stratified across the pixel's samples. A dimension
// the vertex cannot use (the light choice when one light has all the power, roulette before rouletteDepth
// where no resampling takes its value) is skipped, not computed: a value depends only on its dimension's
// index, so skipping gives every other dimension what drawing would.
//
// The first vertex of a camera path takes K light samples, K set by its BRDF (light_count.h), drawn from
// the pixel's pattern of spp × K points (CmjSampler::getSplits2D), and deeper vertices one: what the first
// vertex's light brings is most of the image, and its extra samples share the camera ray and the BSDF
// sample, while a whole extra path would trace both again. A first vertex that takes M > 1 BSDF samples
// (light_count.h) draws them likewise, M split draws of the lobe's and the direction's dimensions, and the
// first of them continues the path. A sheet's panels take the same counts (renderPanels), so that they
// share every draw.
#pragma once

#include "renderer/integrator/lanes.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/samplers/cmj_sampler.h"

#include <cstdint>

namespace glossy {

struct VertexDraws {
  // The draws in the sampler's order, declared once: drawVertices takes them in this order, and their
  // count is the dimensions a vertex owns.
  enum Slot { kLightChoice, kLight, kLobe, kBsdf, kRoulette, kDimensions };
  uint32_t lightCount = 1;  // the light samples drawn, set before drawing
  double lightChoice[kMaxLightSamples] = {};  // which light (LightSet::choose), per light sample
  Vec2 light[kMaxLightSamples] = {};          // where on it (Light::sample)
  double lobe = 0.0;         // which of the BRDF's lobes
  Vec2 bsdf{0.0};            // the direction in that lobe
  // The BSDF samples drawn, set before drawing. Of one sample: lobe and bsdf; else lobes and bsdfs hold them,
  // and each goes into lobe and bsdf before the BRDF samples it (takeBsdfDraw).
  uint32_t bsdfCount = 1;
  double lobes[kMaxBsdfSamples] = {};
  Vec2 bsdfs[kMaxBsdfSamples] = {};
  // Whether the path survives Russian roulette; at a vertex that takes several BSDF samples, which plays no
  // roulette (a first vertex, before RenderSettings::rouletteDepth), which of them is traced (resampling).
  double roulette = 0.0;
};

// The j-th of a vertex's BSDF samples in d, as out's lobe and bsdf (out may be d).
inline void takeBsdfDraw(const VertexDraws& d, int j, VertexDraws& out) {
  if (d.bsdfCount == 1u) {
    out.lobe = d.lobe, out.bsdf = d.bsdf;
  } else {
    out.lobe = d.lobes[j], out.bsdf = d.bsdfs[j];
  }
}

// Which of the skippable draws a vertex at this depth uses.
struct DrawsUsed {
  bool lightChoice, roulette;
  DrawsUsed(const PathContext& context, int depth)
      : lightChoice(context.lights.hasChoice()), roulette(depth >= context.settings.rouletteDepth) {}
};

// The draws of a vertex for samplers[i] into out[i], i in lanes, whose counts the caller has set, slot by
// slot, each a batch draw (cmj_sampler.h), which gives each sampler the values of its scalar draws. The
// light slots of a lane that draws more than one light sample take its split draws
// (CmjSampler::getSplits2D) instead, and the BSDF slots of one that takes more than one BSDF sample its
// split draws of them.
inline void drawVertices(CmjSampler* samplers, const Lanes& lanes, DrawsUsed used, VertexDraws* out) {
  double x[kWaveSize];
  Vec2 xy[kWaveSize];
  uint32_t counts[kWaveSize];
  Vec2* to2D[kWaveSize];
  double* to1D[kWaveSize];
  Lanes single, split, singleBsdf, splitBsdf;
  for (const int i : lanes) (out[i].lightCount == 1u ? single : split).add(i);
  for (const int i : lanes) (out[i].bsdfCount == 1u ? singleBsdf : splitBsdf).add(i);
  for (int slot = 0; slot < VertexDraws::kDimensions; ++slot) {
    if (slot == VertexDraws::kRoulette && !used.roulette) {
      // Roulette is not played: the draw is the resampling's choice where the vertex takes several BSDF
      // samples (Paths::addOtherBsdfSamples), else left as it was.
      CmjSampler::get1D(samplers, splitBsdf.lane, splitBsdf.n, x);
      for (const int i : splitBsdf) out[i].roulette = x[i];
      for (const int i : singleBsdf) samplers[i].skip(1);
    } else if (slot == VertexDraws::kLightChoice && !used.lightChoice) {
      // Left as it was: the choice has one outcome (one light has all the power).
      for (const int i : lanes) samplers[i].skip(1);
    } else {
      const bool light = slot == VertexDraws::kLightChoice || slot == VertexDraws::kLight;
      const bool bsdf = slot == VertexDraws::kLobe || slot == VertexDraws::kBsdf;
      const Lanes& batch = light ? single : bsdf ? singleBsdf : lanes;
      if (bsdf || light) {
        const Lanes& splits = bsdf ? splitBsdf : split;
        for (const int i : splits) {
          counts[i] = bsdf ? out[i].bsdfCount : out[i].lightCount;
          to2D[i] = bsdf ? out[i].bsdfs : out[i].light;
          to1D[i] = bsdf ? out[i].lobes : out[i].lightChoice;
        }
        if (slot == VertexDraws::kBsdf || slot == VertexDraws::kLight) CmjSampler::getSplits2D(samplers, splits.lane, splits.n, counts, to2D);
        else CmjSampler::getSplits1D(samplers, splits.lane, splits.n, counts, to1D);
      }
      const bool is2D = slot == VertexDraws::kLight || slot == VertexDraws::kBsdf;
      if (is2D) CmjSampler::get2D(samplers, batch.lane, batch.n, xy); else CmjSampler::get1D(samplers, batch.lane, batch.n, x);
      for (const int i : batch) {
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
