// The reference path tracer: one path, top to bottom. Unidirectional path tracing with next-event
// estimation (one light, chosen by power, per vertex) combined with BSDF sampling by multiple importance
// sampling (power heuristic), and Russian roulette. The wave (path_wave.cpp) is this, batched; a test holds
// the two to the same image bit for bit.
//
// Depth follows Mitsuba 3: maxDepth counts path segments, so 1 shows only directly visible emitters, 2 adds
// direct lighting, 3 one indirect bounce, and so on.
#include "renderer/integrator/path_vertex.h"

namespace glossy {

Rgb tracePath(const PathContext& context, Ray ray, CmjSampler& sampler) {
  const RenderScene& scene = context.scene;
  const LightSet& lights = context.lights;
  Rgb radiance(0.0);
  PathState path;
  path.from = ray.origin;
  for (int depth = 1;; ++depth) {
    Hit hit;
    if (!scene.bvh->intersect(ray, hit)) {
      // Left the scene: the distant lights.
      for (const ChosenLight& distant : lights.distant()) {
        double pdf = 0.0;
        const Rgb arriving = distant.light->arriving(ray.dir, pdf);
        radiance += path.throughput * weightedEmission(path, arriving, distant.probability * pdf);
      }
      return radiance;
    }
    if (const ChosenLight light = lights.at(hit)) {
      // Emitters are black bodies: they shine and reflect nothing.
      double pdf = 0.0;
      const Rgb emitted = light.light->emitted(hit, path.from, pdf);
      radiance += path.throughput * weightedEmission(path, emitted, light.probability * pdf);
      return radiance;
    }
    ShadingPoint sp;
    if (depth >= context.settings.maxDepth || !shade(scene, ray, hit, sp)) return radiance;
    const VertexDraws u = drawVertex(sampler, DrawsUsed(context, depth));

    // A light sample, traced to the light unless the BRDF sends nothing toward it.
    if (const ChosenLight chosen = lights.choose(u.lightChoice)) {
      LightPath light;
      Rgb contribution;
      if (toLight(sp, chosen, chosen.light->sample(sp.position, u.light), light) &&
          lightContribution(light, valueToward(context.settings, sp, light.wiLocal), contribution) &&
          !scene.bvh->occluded(light.shadow))
        radiance += path.throughput * contribution;
    }

    // A BSDF sample continues the path.
    if (!continuePath(depth, context.settings, sp, sampleBsdf(context.settings, sp, u), u.roulette, path, ray))
      return radiance;
  }
}

}  // namespace glossy
