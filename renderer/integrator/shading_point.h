// Where a path meets a reflecting surface, and what its BRDF does there: its value and density toward a
// direction, and its sample of the next one.
#pragma once

#include "materials/core/frame.h"
#include "renderer/integrator/vertex_draws.h"

#include <glm/geometric.hpp>

namespace glossy {

struct ShadingPoint {
  Vec3 position{0.0}, ng{0.0};  // ng faces the viewer
  double margin = 0.0;          // Hit::margin
  Frame frame{Vec3(0.0, 0.0, 1.0)};
  Vec3 woLocal{0.0};
  const Brdf* brdf = nullptr;
  int lightSamples = 1;  // that the vertex takes (PathContext::lightSamplesAt): its BRDF's, at the first vertex
  int bsdfSamples = 1;   // likewise (PathContext::bsdfSamplesAt): more than one only at a first vertex
};

// The shading point of a hit that is not a light; false where the path cannot reflect there.
inline bool shade(const RenderScene& scene, const Ray& ray, const Hit& hit, ShadingPoint& sp) {
  const Vec3 wo = -ray.dir;
  Vec3 ng, ns;
  normalsFacing(hit, wo, ng, ns);
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

// The BRDF's value toward a direction and the density of its own sampling there; and its samples of the
// paths' next directions. RenderSettings::cosineBrdfSampling samples the cosine lobe instead (to measure
// what a model's own sampling is worth).
inline BrdfValue valueToward(const RenderSettings& settings, const ShadingPoint& sp, const Vec3& wiLocal) {
  if (settings.cosineBrdfSampling) return {eval(*sp.brdf, wiLocal, sp.woLocal), cosineHemispherePdf(wiLocal)};
  return evalPdf(*sp.brdf, wiLocal, sp.woLocal);
}

// out[i]: the BSDF sample of draws u[i] at sp[i], a batch per BRDF.
inline void sampleBsdfs(const RenderSettings& settings, const Lanes& lanes, const ShadingPoint* sp, const VertexDraws* u,
                 BrdfSample* out) {
  if (settings.cosineBrdfSampling) {
    for (const int i : lanes) out[i] = sampleCosineLobe(sp[i].brdf->model(), sp[i].woLocal, u[i].bsdf);
    return;
  }
  forEachGroup(lanes, [&](int i) { return sp[i].brdf; }, [&](const Brdf* brdf, const Lanes& group) {
    // Zeroed only because GCC cannot see that the batch reads the n lanes written.
    Vec3 wo[kWaveSize] = {};
    double uLobe[kWaveSize] = {};
    Vec2 uDir[kWaveSize] = {};
    BrdfSample samples[kWaveSize];
    for (int g = 0; g < group.n; ++g) {
      wo[g] = sp[group.lane[g]].woLocal;
      uLobe[g] = u[group.lane[g]].lobe;
      uDir[g] = u[group.lane[g]].bsdf;
    }
    sampleBatch(*brdf, wo, uLobe, uDir, samples, group.n);
    for (int g = 0; g < group.n; ++g) out[group.lane[g]] = samples[g];
  });
}

}  // namespace glossy
