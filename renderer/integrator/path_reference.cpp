// The reference path tracer: one path, top to bottom. Unidirectional path tracing with next-event
// estimation (one light, chosen by power, per vertex) combined with BSDF sampling by multiple importance
// sampling (power heuristic), and Russian roulette. The wave (path_wave.cpp) is this, batched; a test holds
// the two to the same image bit for bit.
//
// Depth follows Mitsuba 3: maxDepth counts path segments, so 1 shows only directly visible emitters, 2 adds
// direct lighting, 3 one indirect bounce, and so on.
#include "renderer/integrator/path_vertex.h"

namespace glossy {

namespace {

// Follows a path from `ray`, its depth-th segment, adding what it gathers to radiance, until it ends. With
// `stop`, a path that reaches the object stops at that vertex before its BRDF acts, and walk returns true.
bool walk(const PathContext& context, Ray ray, CmjSampler& sampler, PathState& path, int depth, Rgb& radiance,
          ObjectVertex* stop) {
  const RenderScene& scene = context.scene;
  const LightSet& lights = context.lights;
  for (;; ++depth) {
    Hit hit;
    if (!scene.bvh->intersect(ray, hit)) {
      // Left the scene: the distant lights.
      for (const ChosenLight& distant : lights.distant()) {
        double pdf = 0.0;
        const Rgb arriving = distant.light->arriving(ray.dir, path.from, pdf);
        radiance += path.throughput * weightedEmission(path, arriving, distant.probability * pdf);
      }
      return false;
    }
    if (const ChosenLight light = lights.at(hit)) {
      // Emitters are black bodies: they shine and reflect nothing.
      double pdf = 0.0;
      const Rgb emitted = light.light->emitted(hit, path.from, pdf);
      radiance += path.throughput * weightedEmission(path, emitted, light.probability * pdf);
      return false;
    }
    ShadingPoint sp;
    if (depth >= context.settings.maxDepth || !shade(scene, ray, hit, sp)) return false;
    const VertexDraws u = drawVertex(sampler, DrawsUsed(context, depth));
    // A light sample, its shadow ray traced: the same whatever the BRDF.
    const VertexLight light = sampleLight(context, sp, u);
    if (stop && scene.isObject(hit.mesh)) {
      *stop = ObjectVertex{depth, hit.mesh, path, radiance, sp, u, light, sampler};
      return true;
    }
    // The BRDF weighs the light sample, and its sample continues the path.
    if (!reflect(context, depth, sp, u, light, path, radiance, ray)) return false;
  }
}

}  // namespace

Rgb tracePath(const PathContext& context, Ray ray, CmjSampler& sampler) {
  Rgb radiance(0.0);
  PathState path;
  path.from.point = ray.origin;
  walk(context, ray, sampler, path, 1, radiance, nullptr);
  return radiance;
}

bool traceToObject(const PathContext& context, Ray ray, CmjSampler& sampler, Rgb& radiance, ObjectVertex& vertex) {
  radiance = Rgb(0.0);
  vertex.depth = 0;
  PathState path;
  path.from.point = ray.origin;
  return walk(context, ray, sampler, path, 1, radiance, &vertex);
}

Rgb continueFromObject(const PathContext& panel, ObjectVertex v) {
  v.point.brdf = &panel.scene.brdfOf(v.mesh);
  Ray ray;
  if (reflect(panel, v.depth, v.point, v.draws, v.light, v.path, v.radiance, ray))
    walk(panel, ray, v.sampler, v.path, v.depth + 1, v.radiance, nullptr);
  return v.radiance;
}

}  // namespace glossy
