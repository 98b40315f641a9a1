// What a sheet's panels would each compute alike after the object. Every panel continues a path from its
// object vertex with the same sampler, so at each later depth its path reaches, a panel draws the values
// the others draw there (VertexDraws), and a distant light, whose samples depend on the surface's normal
// but not on the point, makes the same sample from them where the panels' paths meet surfaces of the same
// normal (a floor, a wall). The panels' waves on a thread share one SharedDraws: the first
// panel to reach a (path, depth) computes these and keeps them, and the others copy them. So the draws and
// the environment's samples are paid once per path, not once per panel (docs/sheets.md, "Cost").
//
// An entry answers only a sampler in the state it was drawn from (a sampler's values are a function of
// CmjSampler::Key) and a light, normal and draw its sample was made from, so each panel gets exactly what it
// would have computed itself, bit for bit (tests/sheet_coherence_test.cpp).
#pragma once

#include "renderer/integrator/direct_light.h"

#include <algorithm>
#include <vector>

namespace glossy {

class SharedDraws {
 public:
  explicit SharedDraws(int maxDepth) : depths_(std::max(1, maxDepth) + 1), entries_(size_t(depths_) * kWaveSize) {}

  // drawVertices for the lanes at depth (lane i is resumed vertex i): copied where the lane's sampler is in
  // the state of the draws kept for it, drawn and kept elsewhere.
  void draw(int depth, CmjSampler* samplers, const Lanes& lanes, DrawsUsed used, VertexDraws* out) {
    Lanes fresh;
    for (const int i : lanes) {
      Entry& e = entry(depth, i);
      const CmjSampler::Key key = samplers[i].key();
      if (e.sampler == key) {
        out[i] = e.draws;
        samplers[i].skip(VertexDraws::kDimensions);
      } else {
        e.sampler = key;
        fresh.add(i);
      }
    }
    drawVertices(samplers, fresh, used, out);
    for (const int i : fresh) entry(depth, i).draws = out[i];
  }

  // drawLightSamples for the lanes at depth: a distant light's samples copied where the lane's kept sample
  // is of the same light, normal and draw, drawn and kept elsewhere.
  void sampleLight(int depth, const Light* light, const Receiver* at, const Vec2* u, const Lanes& group, LightSample* out) {
    Lanes fresh;
    for (const int i : group) {
      const Kept& kept = entry(depth, i).kept;
      if (light->distant() && kept.light == light && kept.normal == at[i].normal && kept.u == u[i]) out[i] = kept.sample;
      else fresh.add(i);
    }
    drawLightSamples(light, at, u, fresh, out);
    if (light->distant())
      for (const int i : fresh) entry(depth, i).kept = {light, at[i].normal, u[i], out[i]};
  }

 private:
  struct Kept {
    const Light* light = nullptr;  // of sample; null: none kept
    Vec3 normal{0.0};
    Vec2 u{0.0};
    LightSample sample;
  };
  struct Entry {
    CmjSampler::Key sampler;  // the state draws were drawn from (a default key matches no sampler)
    VertexDraws draws;
    Kept kept;
  };
  Entry& entry(int depth, int lane) { return entries_[size_t(std::min(depth, depths_ - 1)) * kWaveSize + size_t(lane)]; }

  int depths_;
  std::vector<Entry> entries_;  // [depth][lane]
};

}  // namespace glossy
