// A path's steps from one vertex to the next, shared by the reference path tracer (path_reference.cpp),
// which takes them one path at a time, the wave (wave_tracer.h), which takes each for many paths at once,
// and the panel split (panel_split.h). All call these functions, so a path gets the same numbers either way.
#pragma once

#include "renderer/integrator/direct_light.h"

namespace glossy {

// A path's state between vertices.
struct PathState {
  PathState() = default;
  explicit PathState(const Vec3& eye) { from.point = eye; }  // a camera path, before its first vertex
  Rgb throughput{1.0};
  double bsdfPdf = 0.0;  // solid-angle pdf of the BSDF sample that made the ray; 0 for the camera ray
  int lightSamples = 1;  // that the vertex the ray left took (MIS counts them)
  Receiver from;         // the vertex the ray left (the light densities of MIS are seen from it)
};

// Emission found by the path's ray (from a light it hit or a distant light it escaped to), weighted
// against the light samples that could have found it, added to radiance with the path's throughput:
// lightPdf is one's density, its light's choice included, and the vertex took path.lightSamples of them
// (the power heuristic with sample counts). A camera ray's is unweighted.
inline void addEmission(const PathState& path, const Rgb& emitted, double lightPdf, Rgb& radiance) {
  radiance += path.throughput *
              (path.bsdfPdf > 0.0 ? emitted * powerHeuristic(path.bsdfPdf, path.lightSamples * lightPdf) : emitted);
}

// What the path's ray hit: a light adds its emission and ends the path (emitters are black bodies: they
// shine and reflect nothing); elsewhere the shading point, if the path reflects there (true).
inline bool arrive(const PathContext& context, const Ray& ray, const Hit& hit, int depth, const PathState& path,
                   Rgb& radiance, ShadingPoint& sp) {
  if (const ChosenLight light = context.lights.at(hit)) {
    double pdf = 0.0;
    const Rgb emitted = light.light->emitted(hit, path.from, pdf);
    addEmission(path, emitted, light.probability * pdf, radiance);
    return false;
  }
  if (depth >= context.settings.maxDepth || !shade(context.scene, ray, hit, sp)) return false;
  sp.lightSamples = context.lightSamplesAt(hit.mesh, depth);
  return true;
}

// The BSDF sample s continues the path: the next ray, the throughput and pdf it carries. False ends it.
inline bool continuePath(int depth, const RenderSettings& settings, const ShadingPoint& sp, const BrdfSample& s,
                         const VertexDraws& u, PathState& path, Ray& ray) {
  if (!s.valid()) return false;
  const Vec3 wi = sp.frame.toWorld(s.L);
  if (glm::dot(wi, sp.ng) <= 0.0) return false;  // below the geometric surface: no leaking through it
  path.throughput *= s.weight;
  path.bsdfPdf = s.pdf;
  path.lightSamples = sp.lightSamples;
  path.from = receiver(sp);
  if (depth >= settings.rouletteDepth) {
    const double survive = std::min(0.95, maxComponent(path.throughput));
    if (u.roulette >= survive) return false;
    path.throughput /= survive;
  }
  ray = spawnRay(sp.position, sp.ng, sp.margin, wi);
  return true;
}

// A reflecting vertex before its BRDF acts: where, its draws, its light samples with their shadow rays.
struct PathVertex {
  uint32_t mesh = 0;
  ShadingPoint point;
  VertexDraws draws;
  VertexLight light;
};

// The path's ray, its depth-th segment, to the next reflecting vertex, adding the emission it finds on the
// way (a light it hits, the distant lights when it leaves the scene). False when the path ends there.
bool nextVertex(const PathContext& context, const Ray& ray, CmjSampler& sampler, int depth, PathState& path,
                Rgb& radiance, PathVertex& vertex);

// The vertex's BRDF acts: the direct light, then its sample continues the path. False ends it.
inline bool reflect(const PathContext& context, int depth, const PathVertex& v, PathState& path, Rgb& radiance, Ray& ray) {
  addDirectLight(context.settings, v.point, v.light, path.throughput, radiance);
  return continuePath(depth, context.settings, v.point, sampleBsdf(context.settings, v.point, v.draws), v.draws, path, ray);
}

// The reference path tracer (path_reference.cpp): the radiance arriving along a camera ray, whose sampler
// has drawn the film position; and the same for a path already at its depth-th segment, adding to radiance.
Rgb Li(const PathContext& context, Ray ray, CmjSampler& sampler);
void finishPath(const PathContext& context, Ray ray, CmjSampler& sampler, PathState& path, int depth, Rgb& radiance);

}  // namespace glossy
