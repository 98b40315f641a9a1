// The steps of a path's vertex, shared by the reference path tracer (path_reference.cpp), which takes them
// one path at a time, and the wave (path_wave.cpp), which takes each for many paths at once. Both call
// these functions, so a path gets the same numbers either way.
#pragma once

#include "materials/core/frame.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/lights/light_set.h"
#include "renderer/sampling/cmj_sampler.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

// What a path tracer works from.
struct PathContext {
  const RenderScene& scene;
  const RenderSettings& settings;
  const LightSet& lights;
};

// The sampler dimensions of a path: the camera's film position (one 2D draw), then at every vertex that
// reflects, these five in this order. Vertex k always owns the same five dimensions, so each stays
// stratified across the pixel's samples. A dimension the vertex cannot use (the light choice when one
// light has all the power, roulette before rouletteDepth) is skipped, not computed: a value depends only on
// its dimension's index, so skipping gives every other dimension what drawing would.
//
// The first vertex of a camera path takes RenderSettings::lightSamples light samples, drawn from the pixel's
// pattern of spp × lightSamples points (CmjSampler::getSplit2D), and deeper vertices one: what the first
// vertex's light brings is most of the image, and its extra samples share the camera ray and the BSDF
// sample, while a whole extra path would trace both again.
struct VertexDraws {
  static constexpr uint32_t kDimensions = 5;  // what drawVertex takes of the sampler
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

// The light draws of a vertex: split draws (as many as the sampler's pattern splits, which is
// RenderSettings::lightSamples) at the first vertex, one elsewhere.
inline void drawLights(CmjSampler& sampler, DrawsUsed used, VertexDraws& d) {
  d.lightSamples = used.lightSamples > 1 ? int(sampler.splits()) : 1;
  if (d.lightSamples > 1) {
    if (used.lightChoice) sampler.getSplit1D(d.lightChoice); else sampler.skip(1);
    sampler.getSplit2D(d.light);
  } else {
    if (used.lightChoice) d.lightChoice[0] = sampler.get1D(); else sampler.skip(1);
    d.light[0] = sampler.get2D();
  }
}

inline VertexDraws drawVertex(CmjSampler& sampler, DrawsUsed used) {
  VertexDraws d;
  drawLights(sampler, used, d);
  d.lobe = sampler.get1D();
  d.bsdf = sampler.get2D();
  if (used.roulette) d.roulette = sampler.get1D(); else sampler.skip(1);
  return d;
}

// Paths traced together by the wave.
constexpr int kWaveSize = 128;

// drawVertex for samplers[lanes[k]], k < n, into out[lanes[k]] (lanes < kWaveSize): the batch draws
// (cmj_sampler.h), the same values in the same order.
inline void drawVertices(CmjSampler* samplers, const int* lanes, int n, DrawsUsed used, VertexDraws* out) {
  double choice[kWaveSize], lobe[kWaveSize], roulette[kWaveSize];
  Vec2 light[kWaveSize], bsdf[kWaveSize];
  const auto skip = [&] {
    for (int k = 0; k < n; ++k) samplers[lanes[k]].skip(1);
  };
  if (used.lightSamples > 1) {
    for (int k = 0; k < n; ++k) drawLights(samplers[lanes[k]], used, out[lanes[k]]);
  } else {
    if (used.lightChoice) CmjSampler::get1D(samplers, lanes, n, choice); else skip();
    CmjSampler::get2D(samplers, lanes, n, light);
  }
  CmjSampler::get1D(samplers, lanes, n, lobe);
  CmjSampler::get2D(samplers, lanes, n, bsdf);
  if (used.roulette) CmjSampler::get1D(samplers, lanes, n, roulette); else skip();
  for (int k = 0; k < n; ++k) {
    const int i = lanes[k];
    VertexDraws& d = out[i];
    if (used.lightSamples == 1) {
      d.lightSamples = 1;
      d.lightChoice[0] = used.lightChoice ? choice[i] : 0.0;
      d.light[0] = light[i];
    }
    d.lobe = lobe[i];
    d.bsdf = bsdf[i];
    d.roulette = used.roulette ? roulette[i] : 0.0;
  }
}

inline double powerHeuristic(double a, double b) {
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

inline double maxComponent(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

// A path's state between vertices.
struct PathState {
  Rgb throughput{1.0};
  double bsdfPdf = 0.0;  // solid-angle pdf of the BSDF sample that made the ray; 0 for the camera ray
  int lightSamples = 1;  // that the vertex the ray left took (MIS counts them)
  Receiver from;         // the vertex the ray left (the light densities of MIS are seen from it)
};

// Emission found by the path's ray (from a light it hit or a distant light it escaped to), weighted
// against the light samples that could have found it: lightPdf is one's density, its light's choice
// included, and the vertex took path.lightSamples of them (the power heuristic with sample counts). A
// camera ray's is unweighted.
inline Rgb weightedEmission(const PathState& path, const Rgb& emitted, double lightPdf) {
  return path.bsdfPdf > 0.0 ? emitted * powerHeuristic(path.bsdfPdf, path.lightSamples * lightPdf) : emitted;
}

// Where a path meets a reflecting surface.
struct ShadingPoint {
  Vec3 position{0.0}, ng{0.0};  // ng faces the viewer
  double margin = 0.0;          // Hit::margin
  Frame frame{Vec3(0.0, 0.0, 1.0)};
  Vec3 woLocal{0.0};
  const Brdf* brdf = nullptr;
};

// The shading point of a hit that is not a light; false where the path cannot reflect there.
inline bool shade(const RenderScene& scene, const Ray& ray, const Hit& hit, ShadingPoint& sp) {
  const Vec3 wo = -ray.dir;
  // Two-sided shading: face the normals toward the viewer. A shading normal that still faces away
  // would let light through the surface, so fall back to the geometric one there.
  Vec3 ng = hit.geometricNormal, ns = hit.shadingNormal;
  if (glm::dot(wo, ng) < 0.0) {
    ng = -ng;
    ns = -ns;
  }
  if (glm::dot(wo, ns) <= 0.0) ns = ng;
  sp.position = hit.position;
  sp.ng = ng;
  sp.margin = hit.margin;
  sp.frame = Frame(ns);
  sp.woLocal = sp.frame.toLocal(wo);
  sp.brdf = &scene.brdfOf(hit.mesh);
  return sp.woLocal.z > 0.0;
}

// The shading point as its lights see it.
inline Receiver receiver(const ShadingPoint& sp) { return {sp.position, sp.frame.n}; }

// A light sample as the shading point sees it: the shadow ray to trace and what the light brings along it,
// before the BRDF's value there.
struct LightPath {
  Vec3 wiLocal{0.0};
  Rgb radiance{0.0};
  double pdf = 0.0;  // solid angle, the light's choice included
  bool delta = false;  // LightSample::delta: no BSDF sample competes with it
  Ray shadow;        // tfar < 0: nothing can lie between (the light touches the point)
};

// False when the sample brings nothing.
inline bool toLight(const ShadingPoint& sp, const ChosenLight& chosen, const LightSample& s, LightPath& out) {
  if (!(s.pdf > 0.0) || glm::dot(s.wi, sp.ng) <= 0.0) return false;
  out.wiLocal = sp.frame.toLocal(s.wi);
  if (out.wiLocal.z <= 0.0) return false;
  out.radiance = s.radiance;
  out.pdf = chosen.probability * s.pdf;
  out.delta = s.delta;
  out.shadow = spawnRay(sp.position, sp.ng, sp.margin, s.wi);
  if (!s.distant) {
    // To the light's point, itself moved off the light by its margin. Where the two margins overlap
    // there is no room for an occluder: the light is seen.
    const Vec3 d = s.target - out.shadow.origin;
    const double length = glm::length(d);
    const bool room = glm::dot(d, s.wi) > 0.0 && length > 0.0;
    out.shadow.dir = room ? d / length : s.wi;
    out.shadow.tfar = room ? length : -1.0;
  }
  return true;
}

// The light samples of a vertex with their shadow rays' verdicts: none of it depends on the vertex's BRDF,
// so the panels of a sheet share it (ObjectVertex).
struct VertexLight {
  int count = 0;
  LightPath path[kMaxLightSamples];
  bool visible[kMaxLightSamples] = {};  // the sample arrived from above the surface and nothing blocks it
};
inline VertexLight sampleLight(const PathContext& context, const ShadingPoint& sp, const VertexDraws& u) {
  VertexLight v;
  v.count = u.lightSamples;
  for (int k = 0; k < v.count; ++k)
    if (const ChosenLight chosen = context.lights.choose(u.lightChoice[k]))
      v.visible[k] = toLight(sp, chosen, chosen.light->sample(receiver(sp), u.light[k]), v.path[k]) &&
                     !context.scene.bvh->occluded(v.path[k].shadow);
  return v;
}

// What one of a vertex's `count` light samples brings if nothing blocks it, MIS-weighted against the
// BRDF's own sampling (the power heuristic with sample counts; weight 1 for a delta light, which no BSDF
// sample finds), before the path's throughput. False when that is nothing.
inline bool lightContribution(const LightPath& light, int count, const BrdfValue& value, Rgb& contribution) {
  if (maxComponent(value.f) <= 0.0) return false;
  const double pdf = count * light.pdf;
  const double w = light.delta ? 1.0 : powerHeuristic(pdf, value.pdf);
  contribution = value.f * light.radiance * (light.wiLocal.z * w / pdf);
  return true;
}

// The BRDF's value toward a light sample and the density of its own sampling there; and its sample of
// the path's next direction. RenderSettings::cosineBrdfSampling samples the cosine lobe instead (to
// measure what a model's own sampling is worth).
inline BrdfValue valueToward(const RenderSettings& settings, const ShadingPoint& sp, const Vec3& wiLocal) {
  if (settings.cosineBrdfSampling) return {eval(*sp.brdf, wiLocal, sp.woLocal), cosineHemispherePdf(wiLocal)};
  return evalPdf(*sp.brdf, wiLocal, sp.woLocal);
}
inline BrdfSample sampleBsdf(const RenderSettings& settings, const ShadingPoint& sp, const VertexDraws& u) {
  if (settings.cosineBrdfSampling) return sampleCosineLobe(sp.brdf->model(), sp.woLocal, u.bsdf);
  return sample(*sp.brdf, sp.woLocal, u.lobe, u.bsdf);
}

// The BSDF sample s continues the path: the next ray, the throughput and pdf it carries. False ends it.
inline bool continuePath(int depth, const RenderSettings& settings, const ShadingPoint& sp, const BrdfSample& s,
                         const VertexDraws& u, PathState& path, Ray& ray) {
  const double uRoulette = u.roulette;
  if (!s.valid()) return false;
  const Vec3 wi = sp.frame.toWorld(s.L);
  if (glm::dot(wi, sp.ng) <= 0.0) return false;  // below the geometric surface: no leaking through it
  path.throughput *= s.weight;
  path.bsdfPdf = s.pdf;
  path.lightSamples = u.lightSamples;
  path.from = receiver(sp);
  if (depth >= settings.rouletteDepth) {
    const double survive = std::min(0.95, maxComponent(path.throughput));
    if (uRoulette >= survive) return false;
    path.throughput /= survive;
  }
  ray = spawnRay(sp.position, sp.ng, sp.margin, wi);
  return true;
}

// What a vertex's BRDF does with its draws: weighs the light sample (adding it when nothing blocks it) and
// samples the path's next direction. False ends the path.
inline bool reflect(const PathContext& context, int depth, const ShadingPoint& sp, const VertexDraws& u,
                    const VertexLight& light, PathState& path, Rgb& radiance, Ray& ray) {
  for (int k = 0; k < light.count; ++k) {
    Rgb contribution;
    if (light.visible[k] &&
        lightContribution(light.path[k], light.count, valueToward(context.settings, sp, light.path[k].wiLocal), contribution))
      radiance += path.throughput * contribution;
  }
  return continuePath(depth, context.settings, sp, sampleBsdf(context.settings, sp, u), u, path, ray);
}

// A path at its first vertex on a sheet's object (RenderScene::objectMeshes), before the vertex's BRDF is
// used: all that the panels share, from which each continues with its own BRDF.
struct ObjectVertex {
  int depth = 0;           // 0: the path never reached the object
  uint32_t mesh = 0;
  PathState path;
  Rgb radiance{0.0};       // gathered before the vertex
  ShadingPoint point;      // its brdf is the first panel's; each panel sets its own
  VertexDraws draws;
  VertexLight light;
  CmjSampler sampler;      // past the vertex's draws
};

// The reference path tracer: the radiance arriving along a camera ray, whose sampler has drawn the film
// position.
Rgb tracePath(const PathContext& context, Ray ray, CmjSampler& sampler);
// The same, but a path that reaches the object stops there (returning true, the radiance so far in
// vertex.radiance; vertex.depth is 0 when it did not stop); continueFromObject then finishes it for a panel, whose context differs only in the
// object's BRDF. The two make exactly tracePath's radiance.
bool traceToObject(const PathContext& context, Ray ray, CmjSampler& sampler, Rgb& radiance, ObjectVertex& vertex);
Rgb continueFromObject(const PathContext& panel, ObjectVertex vertex);

// A list of a wave's lanes.
struct Lanes {
  int lane[kWaveSize];
  int n = 0;
  void add(int i) { lane[n++] = i; }
};

class SharedDraws;

// tracePath for up to kWaveSize camera rays at once: radiance[i] for the lanes with start[i]. With stops,
// traceToObject instead: a lane whose path reaches the object stops there, stops[i] its vertex (depth 0 for
// the others). continueFromObject for n vertices of one depth: resume. Its lanes' state lives in the
// tracer, made once per thread and reused, as it is too large to clear per wave. The panels' tracers of a
// thread may share a SharedDraws (shared_draws.h), which resume then uses.
class WaveTracer {
 public:
  explicit WaveTracer(const PathContext& context, SharedDraws* shared = nullptr) : context_(context), shared_(shared) {}
  void trace(Ray* rays, CmjSampler* samplers, const bool* start, Rgb* radiance, ObjectVertex* stops = nullptr);
  void resume(const ObjectVertex* vertices, int n, Rgb* radiance);

 private:
  void walk(int depth, Ray* rays, CmjSampler* samplers, bool* alive, Rgb* radiance, ObjectVertex* stops);
  void sampleLights(int depth, const Lanes& lanes, SharedDraws* shared);
  void reflectAll(int depth, const Lanes& lanes, Ray* rays, bool* alive, Rgb* radiance);
  void sampleBrdf(const Brdf& brdf, const int* lanes, int n);
  void evalBrdf(const Brdf& brdf, int j, const int* lanes, int n);

  const PathContext& context_;
  SharedDraws* shared_;
  PathState path_[kWaveSize];
  Hit hit_[kWaveSize];
  bool found_[kWaveSize];
  Vec3 direction_[kWaveSize];  // of the rays that left the scene
  Rgb arriving_[kWaveSize];
  double pdf_[kWaveSize];
  ShadingPoint point_[kWaveSize];
  VertexDraws draws_[kWaveSize];
  ChosenLight chosen_[kWaveSize];
  Receiver from_[kWaveSize];  // the escaped rays' vertices; the shading points as their lights see them
  Vec2 uLight_[kWaveSize];
  LightSample lightSample_[kWaveSize];
  BrdfSample bsdfSample_[kWaveSize];
  VertexLight light_[kWaveSize];
  BrdfValue value_[kWaveSize];
  Ray shadow_[kWaveSize];
  bool shadowed_[kWaveSize], occluded_[kWaveSize];
  Ray resumeRays_[kWaveSize];
  CmjSampler resumeSamplers_[kWaveSize];
};

}  // namespace glossy
