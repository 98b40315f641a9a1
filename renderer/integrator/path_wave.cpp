// The wave (wave_tracer.h). Rays go to Embree as packets of kPacketSize lanes; the sampler's draws, the
// direct-light step (direct_light.h) and the BRDFs' samples are batch calls, whose long chains of
// arithmetic and cache misses overlap across lanes. Every lane takes the steps the reference takes, in
// its order, with the same draws, so each lane's radiance is the reference's bit for bit.
#include "renderer/integrator/panel_split.h"

#include <algorithm>

namespace glossy {

static_assert(kWaveSize % kPacketSize == 0, "a wave is whole Embree packets");

void WaveTracer::trace(Ray* rays, CmjSampler* samplers, int n, Rgb* radiance, ObjectVertex* stops) {
  bool alive[kWaveSize];
  for (int i = 0; i < kWaveSize; ++i) {
    alive[i] = i < n;
    radiance[i] = Rgb(0.0);
    path_[i] = PathState(rays[i].origin);
    if (stops) stops[i].depth = 0;
  }
  walk(1, rays, samplers, alive, radiance, stops);
}

void WaveTracer::resume(const ObjectVertex* vertices, int n, Rgb* radiance) {
  bool alive[kWaveSize] = {};
  for (int i = 0; i < n; ++i) {
    const ObjectVertex& v = vertices[i];
    path_[i] = v.path;
    radiance[i] = v.radiance;
    point_[i] = v.vertex.point;
    point_[i].brdf = &context_.scene.brdfOf(v.vertex.mesh);
    point_[i].lightSamples = context_.lightSamplesAt(v.vertex.mesh, v.depth);
    draws_[i] = v.vertex.draws;
    light_[i] = v.vertex.light;
    resumeSamplers_[i] = v.sampler;
  }
  if (n == 0) return;
  reflectAll(vertices[0].depth, Lanes::first(n), resumeRays_, alive, radiance);
  walk(vertices[0].depth + 1, resumeRays_, resumeSamplers_, alive, radiance, nullptr);
}

void WaveTracer::walk(int depth, Ray* rays, CmjSampler* samplers, bool* alive, Rgb* radiance, ObjectVertex* stops) {
  for (;; ++depth) {
    if (std::none_of(alive, alive + kWaveSize, [](bool a) { return a; })) return;
    for (int p = 0; p < kWaveSize; p += kPacketSize) context_.scene.bvh->intersect(alive + p, rays + p, hit_ + p, found_ + p);

    // Rays that left the scene see the distant lights; rays that hit a light see it; the others shade, and
    // with stops those on the object stop there once their light sample is taken.
    Lanes escaped, shading, reflecting;
    bool stopping[kWaveSize] = {};
    for (int i = 0; i < kWaveSize; ++i) {
      if (!alive[i]) continue;
      alive[i] = false;
      if (!found_[i]) {
        escaped.add(i);
        direction_[i] = rays[i].dir;
        from_[i] = path_[i].from;
      } else if (arrive(context_, rays[i], hit_[i], depth, path_[i], radiance[i], point_[i])) {
        shading.add(i);
        stopping[i] = stops && context_.scene.isObject(hit_[i].mesh);
        if (!stopping[i]) reflecting.add(i);
      }
    }
    for (const ChosenLight& distant : context_.lights.distant()) {
      distant.light->arriving(direction_, from_, escaped.lane, escaped.n, arriving_, pdf_);
      for (const int i : escaped) addEmission(path_[i], arriving_[i], distant.probability * pdf_[i], radiance[i]);
    }
    // Resumed paths share what the panels draw alike; the paths before the object are traced once anyway.
    SharedDraws* shared = stops ? nullptr : shared_;
    for (const int i : shading) draws_[i].lightSets = context_.lightSetsAt(hit_[i].mesh, depth);
    if (shared)
      shared->draw(depth, samplers, shading, DrawsUsed(context_, depth), draws_);
    else
      drawVertices(samplers, shading, DrawsUsed(context_, depth), draws_);
    direct_.sample(context_, shading, point_, draws_, light_,
                   [&](const Light* light, const Receiver* at, const Vec2* u, const Lanes& group, LightSample* out) {
                     if (shared) shared->sampleLight(depth, light, at, u, group, out);
                     else drawLightSamples(light, at, u, group, out);
                   });
    for (const int i : shading)
      if (stopping[i]) stops[i] = ObjectVertex{depth, path_[i], radiance[i], {hit_[i].mesh, point_[i], draws_[i], light_[i]}, samplers[i]};
    reflectAll(depth, reflecting, rays, alive, radiance);
  }
}

// reflect for the lanes: the direct light, then the BSDF samples, a batch per BRDF; then the paths go on
// (alive).
void WaveTracer::reflectAll(int depth, const Lanes& lanes, Ray* rays, bool* alive, Rgb* radiance) {
  for (const int i : lanes) throughput_[i] = path_[i].throughput;
  direct_.add(context_.settings, lanes, point_, light_, throughput_, radiance);
  forEachGroup(lanes, [&](int i) { return point_[i].brdf; }, [&](const Brdf* brdf, const Lanes& group) { sampleBrdf(*brdf, group); });
  for (const int i : lanes)
    alive[i] = continuePath(depth, context_.settings, point_[i], bsdfSample_[i], draws_[i], path_[i], rays[i]);
}

// bsdfSample_ of a group of one BRDF: sampleBsdf, as one batch.
void WaveTracer::sampleBrdf(const Brdf& brdf, const Lanes& group) {
  if (context_.settings.cosineBrdfSampling) {
    for (const int i : group) bsdfSample_[i] = sampleBsdf(context_.settings, point_[i], draws_[i]);
    return;
  }
  // Zeroed only because GCC cannot see that the batch reads the n lanes written.
  Vec3 wo[kWaveSize] = {};
  double uLobe[kWaveSize] = {};
  Vec2 u[kWaveSize] = {};
  BrdfSample samples[kWaveSize];
  for (int g = 0; g < group.n; ++g) {
    wo[g] = point_[group.lane[g]].woLocal;
    uLobe[g] = draws_[group.lane[g]].lobe;
    u[g] = draws_[group.lane[g]].bsdf;
  }
  sampleBatch(brdf, wo, uLobe, u, samples, group.n);
  for (int g = 0; g < group.n; ++g) bsdfSample_[group.lane[g]] = samples[g];
}

}  // namespace glossy
