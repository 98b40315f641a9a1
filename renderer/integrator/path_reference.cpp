// The path tracer, as pbrt-v4's PathIntegrator::Li, for a set of lanes (path_vertex.h: the reference's one
// path, the wave's kWaveSize). Unidirectional path tracing with next-event estimation (direct_light.h: at a
// camera path's first vertex as many light samples as its BRDF takes, light_count.h, one at each deeper
// one, each of a light chosen by power) combined with BSDF sampling by multiple importance sampling (power
// heuristic), and Russian roulette. A test holds the reference and the wave to the same image bit for bit.
//
// Depth follows Mitsuba 3: maxDepth counts path segments, so 1 shows only directly visible emitters, 2 adds
// direct lighting, 3 one indirect bounce, and so on.
#include "renderer/integrator/path_vertex.h"
#include "renderer/integrator/shared_draws.h"

namespace glossy {

template <int N>
Lanes Paths<N>::next(int depth, const Lanes& lanes, const Ray* rays, CmjSampler* samplers, Rgb* radiance, SharedDraws* shared) {
  // The rays' hits: as Embree packets where N is whole packets (a wave's), else one at a time.
  if constexpr (N % kPacketSize == 0) {
    bool active[N] = {};
    for (const int i : lanes) active[i] = true;
    for (int p = 0; p < N; p += kPacketSize) context_.scene.bvh->intersect(active + p, rays + p, hit + p, found_ + p);
  } else {
    for (const int i : lanes) found_[i] = context_.scene.bvh->intersect(rays[i], hit[i]);
  }
  // A ray that left the scene sees the distant lights; one that hit a light sees it, and its path ends there;
  // the others find the shading point, where their paths reflect if they can.
  Lanes escaped, shading;
  for (const int i : lanes) {
    if (!found_[i]) {
      escaped.add(i);
      direction_[i] = rays[i].dir;
      from_[i] = path[i].from;
    } else if (arrive(context_, rays[i], hit[i], depth, path[i], radiance[i], point[i])) {
      shading.add(i);
    }
  }
  for (const ChosenLight& distant : context_.lights.distant()) {
    distant.light->arriving(direction_, from_, escaped.lane, escaped.n, arriving_, pdf_);
    for (const int i : escaped) addEmission(path[i], arriving_[i], distant.probability * pdf_[i], radiance[i]);
  }
  // The vertices' draws, then their light samples with their shadow rays' verdicts.
  for (const int i : shading) draws[i].lightSets = context_.lightSetsAt(hit[i].mesh, depth);
  if (shared)
    shared->draw(depth, samplers, shading, DrawsUsed(context_, depth), draws);
  else
    drawVertices(samplers, shading, DrawsUsed(context_, depth), draws);
  direct_.sample(context_, shading, point, draws, light,
                 [&](const Light* l, const Receiver* at, const Vec2* u, const Lanes& group, LightSample* out) {
                   if (shared) shared->sampleLight(depth, l, at, u, group, out);
                   else drawLightSamples(l, at, u, group, out);
                 });
  return shading;
}

template <int N>
Lanes Paths<N>::reflect(int depth, const Lanes& lanes, Ray* rays, Rgb* radiance) {
  // The direct light, weighed by the BRDFs; then the BSDF samples, which continue the paths.
  for (const int i : lanes) throughput_[i] = path[i].throughput;
  direct_.add(context_.settings, lanes, point, light, throughput_, radiance);
  sampleBsdfs<N>(context_.settings, lanes, point, draws, bsdf_);
  Lanes alive;
  for (const int i : lanes)
    if (continuePath(depth, context_.settings, point[i], bsdf_[i], draws[i], path[i], rays[i])) alive.add(i);
  return alive;
}

template class Paths<1>;
template class Paths<kWaveSize>;

}  // namespace glossy
