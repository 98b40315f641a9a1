// The reference path tracer: one path, top to bottom, as pbrt-v4's PathIntegrator::Li. Unidirectional path
// tracing with next-event estimation (direct_light.h: at a camera path's first vertex as many light samples
// as its BRDF takes, light_count.h, one at each deeper one, each of a light chosen by power) combined with
// BSDF sampling by multiple importance sampling (power heuristic), and Russian roulette. The wave
// (wave_tracer.h) is this, batched; a test holds the two to the same image bit for bit.
//
// Depth follows Mitsuba 3: maxDepth counts path segments, so 1 shows only directly visible emitters, 2 adds
// direct lighting, 3 one indirect bounce, and so on.
#include "renderer/integrator/path_vertex.h"

namespace glossy {

bool nextVertex(const PathContext& context, const Ray& ray, CmjSampler& sampler, int depth, PathState& path,
                Rgb& radiance, PathVertex& vertex) {
  Hit hit;
  if (!context.scene.bvh->intersect(ray, hit)) {
    // Left the scene: the distant lights.
    for (const ChosenLight& distant : context.lights.distant()) {
      double pdf = 0.0;
      const Rgb arriving = distant.light->arriving(ray.dir, path.from, pdf);
      addEmission(path, arriving, distant.probability * pdf, radiance);
    }
    return false;
  }
  if (!arrive(context, ray, hit, depth, path, radiance, vertex.point)) return false;
  vertex.mesh = hit.mesh;
  vertex.draws.lightSets = context.lightSetsAt(hit.mesh, depth);
  drawVertices(&sampler, Lanes::first(1), DrawsUsed(context, depth), &vertex.draws);
  vertex.light = sampleLight(context, vertex.point, vertex.draws);
  return true;
}

void finishPath(const PathContext& context, Ray ray, CmjSampler& sampler, PathState& path, int depth, Rgb& radiance) {
  for (PathVertex v; nextVertex(context, ray, sampler, depth, path, radiance, v); ++depth)
    if (!reflect(context, depth, v, path, radiance, ray)) return;
}

Rgb Li(const PathContext& context, Ray ray, CmjSampler& sampler) {
  Rgb radiance(0.0);
  PathState path(ray.origin);
  finishPath(context, ray, sampler, path, 1, radiance);
  return radiance;
}

}  // namespace glossy
