// Next-event estimation, the direct-light step of a vertex: its light samples (a light chosen by power,
// a point on it, the shadow ray), then each weighed by the vertex's BRDF and by multiple importance
// sampling against the BRDF's own sampling (the power heuristic with sample counts; weight 1 for a delta
// light, which no BSDF sample finds). The samples and their shadow rays do not depend on the BRDF, so a
// sheet's panels share them (panel_split.h); the BRDF's weighing is each panel's.
#pragma once

#include "renderer/integrator/shading_point.h"

#include <algorithm>

namespace glossy {

inline double powerHeuristic(double a, double b) {
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

inline double maxComponent(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

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

// The light samples a vertex drew (VertexDraws::lightSets, a set per count its panels take) with their
// shadow rays' verdicts.
struct VertexLight {
  uint32_t sets = 1;
  int count = 0;  // lightDraws(sets)
  LightPath path[kMaxLightDraws];
  bool visible[kMaxLightDraws] = {};  // the sample arrived from above the surface and nothing blocks it
};
inline VertexLight sampleLight(const PathContext& context, const ShadingPoint& sp, const VertexDraws& u) {
  VertexLight v;
  v.sets = u.lightSets;
  v.count = lightDraws(u.lightSets);
  for (int k = 0; k < v.count; ++k)
    if (const ChosenLight chosen = context.lights.choose(u.lightChoice[k]))
      v.visible[k] = toLight(sp, chosen, chosen.light->sample(receiver(sp), u.light[k]), v.path[k]) &&
                     !context.scene.bvh->occluded(v.path[k].shadow);
  return v;
}

// What one of a vertex's `count` light samples brings if nothing blocks it, MIS-weighted, before the
// path's throughput. False when that is nothing.
inline bool lightContribution(const LightPath& light, int count, const BrdfValue& value, Rgb& contribution) {
  if (maxComponent(value.f) <= 0.0) return false;
  const double pdf = count * light.pdf;
  const double w = light.delta ? 1.0 : powerHeuristic(pdf, value.pdf);
  contribution = value.f * light.radiance * (light.wiLocal.z * w / pdf);
  return true;
}

// The vertex's light samples weighed by its BRDF, added to radiance with the path's throughput: the set
// of sp.lightSamples of them.
inline void addDirectLight(const RenderSettings& settings, const ShadingPoint& sp, const VertexLight& light,
                           const Rgb& throughput, Rgb& radiance) {
  const int first = lightOffset(light.sets, sp.lightSamples);
  for (int k = first; k < first + sp.lightSamples; ++k) {
    Rgb contribution;
    if (light.visible[k] &&
        lightContribution(light.path[k], sp.lightSamples, valueToward(settings, sp, light.path[k].wiLocal), contribution))
      radiance += throughput * contribution;
  }
}

}  // namespace glossy
