// The path tracer, as pbrt-v4's PathIntegrator::Li, for a set of lanes (path_vertex.h: the reference's one
// path, the wave's kWaveSize). Unidirectional path tracing with next-event estimation (direct_light.h: at a
// camera path's first vertex as many light samples as its BRDF takes, light_count.h, one at each deeper
// one, each of a light chosen by power) combined with BSDF sampling by multiple importance sampling (power
// heuristic with sample counts: a first vertex takes as many BSDF samples as its BRDF takes, of which the
// first continues the path), and Russian roulette. A test holds the reference and the wave to the same
// image bit for bit.
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
  addDistantEmission(escaped, path, radiance);
  // The vertices' draws, then their light samples with their shadow rays' verdicts.
  for (const int i : shading) draws[i].lightSets = context_.lightSetsAt(hit[i].mesh, depth);
  for (const int i : shading) draws[i].bsdfSets = context_.bsdfSetsAt(hit[i].mesh, depth);
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
  for (const int i : lanes) takeBsdfDraw(draws[i], point[i].bsdfSamples, 0, draws[i]);
  sampleBsdfs<N>(context_.settings, lanes, point, draws, bsdf_);
  Lanes more;
  for (const int i : lanes)
    if (point[i].bsdfSamples > 1) more.add(i);
  if (more.n > 0) addOtherBsdfSamples(more, radiance);
  Lanes alive;
  for (const int i : lanes)
    if (continuePath(depth, context_.settings, point[i], bsdf_[i], draws[i], path[i], rays[i])) alive.add(i);
  return alive;
}

template <int N>
void Paths<N>::addOtherBsdfSamples(const Lanes& lanes, Rgb* radiance) {
  int most = 1;
  for (const int i : lanes) most = std::max(most, point[i].bsdfSamples);
  for (int j = 1; j < most; ++j) {
    Lanes sampled;
    for (const int i : lanes)
      if (j < point[i].bsdfSamples) {
        takeBsdfDraw(draws[i], point[i].bsdfSamples, j, otherDraws_[i]);
        sampled.add(i);
      }
    sampleBsdfs<N>(context_.settings, sampled, point, otherDraws_, other_);
    Lanes traced;
    bool active[N] = {};
    for (const int i : sampled) {
      const BrdfSample& s = other_[i];
      if (!s.valid()) continue;
      const Vec3 wi = point[i].frame.toWorld(s.L);
      if (glm::dot(wi, point[i].ng) <= 0.0) continue;
      otherRays_[i] = spawnRay(point[i].position, point[i].ng, point[i].margin, wi);
      PathState& p = otherPath_[i];
      p.throughput = path[i].throughput * s.weight;
      p.bsdfPdf = s.pdf;
      p.lightSamples = point[i].lightSamples;
      p.bsdfSamples = point[i].bsdfSamples;
      p.from = receiver(point[i]);
      active[i] = true;
      traced.add(i);
    }
    if constexpr (N % kPacketSize == 0) {
      for (int p = 0; p < N; p += kPacketSize) context_.scene.bvh->intersect(active + p, otherRays_ + p, otherHit_ + p, otherFound_ + p);
    } else {
      for (const int i : traced) otherFound_[i] = context_.scene.bvh->intersect(otherRays_[i], otherHit_[i]);
    }
    Lanes escaped;
    for (const int i : traced) {
      if (!otherFound_[i]) {
        escaped.add(i);
        direction_[i] = otherRays_[i].dir;
        from_[i] = otherPath_[i].from;
      } else if (const ChosenLight light = context_.lights.at(otherHit_[i])) {
        double pdf = 0.0;
        const Rgb emitted = light.light->emitted(otherHit_[i], otherPath_[i].from, pdf);
        addEmission(otherPath_[i], emitted, light.probability * pdf, radiance[i]);
      }
    }
    addDistantEmission(escaped, otherPath_, radiance);
  }
}

template <int N>
void Paths<N>::addDistantEmission(const Lanes& escaped, const PathState* paths, Rgb* radiance) {
  for (const ChosenLight& distant : context_.lights.distant()) {
    distant.light->arriving(direction_, from_, escaped.lane, escaped.n, arriving_, pdf_);
    for (const int i : escaped) addEmission(paths[i], arriving_[i], distant.probability * pdf_[i], radiance[i]);
  }
}

template class Paths<1>;
template class Paths<kWaveSize>;

}  // namespace glossy
