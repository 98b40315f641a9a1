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

// The BRDF's value toward a direction and the density of its own sampling there; and its sample of
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

}  // namespace glossy
