// What a sheet's panels would each compute alike after the object. Every panel continues a path from its
// object vertex with the same sampler, so at each later depth its path reaches, a panel draws the values
// the others draw there (VertexDraws), and a distant light, whose samples depend on the surface's normal
// but not on the point, makes the same sample from them where the panels' paths meet surfaces of the same
// normal (a floor, a wall). The panels' wave tracers on a thread share one SharedDraws: the first
// panel to reach a (path, depth) computes these and keeps them, and the others copy them. So the draws and
// the environment's samples are paid once per path, not once per panel (docs/sheets.md, "Cost").
//
// An entry answers only a sampler in the state it was drawn from (a sampler's values are a function of
// CmjSampler::Key) and a light, normal and draw its sample was made from, so each panel gets exactly what it
// would have computed itself, bit for bit (tests/sheet_coherence_test.cpp).
#pragma once

#include "renderer/integrator/wave_tracer.h"

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
      Entry& e = at(depth, i);
      const CmjSampler::Key key = samplers[i].key();
      if (e.sampler == key) {
        out[i] = e.draws;
        samplers[i].skip(VertexDraws::kDimensions);
      } else {
        e.sampler = key;
        fresh.add(i);
      }
    }
    drawVertices(samplers, fresh.lane, fresh.n, used, out);
    for (const int i : fresh) at(depth, i).draws = out[i];
  }

  // The sample the distant `light` made toward `normal` from draw u for the lane at depth, if one is kept.
  const LightSample* find(int depth, int lane, const Light* light, const Vec3& normal, Vec2 u) {
    const Entry& e = at(depth, lane);
    return e.light == light && e.normal == normal && e.u == u ? &e.sample : nullptr;
  }
  void keep(int depth, int lane, const Light* light, const Vec3& normal, Vec2 u, const LightSample& sample) {
    Entry& e = at(depth, lane);
    e.light = light;
    e.normal = normal;
    e.u = u;
    e.sample = sample;
  }

 private:
  struct Entry {
    CmjSampler::Key sampler;  // the state draws were drawn from (a default key matches no sampler)
    VertexDraws draws;
    const Light* light = nullptr;  // of sample; null: none kept
    Vec3 normal{0.0};
    Vec2 u{0.0};
    LightSample sample;
  };
  Entry& at(int depth, int lane) { return entries_[size_t(std::min(depth, depths_ - 1)) * kWaveSize + size_t(lane)]; }

  int depths_;
  std::vector<Entry> entries_;  // [depth][lane]
};

}  // namespace glossy
