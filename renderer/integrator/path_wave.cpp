// The wave (wave_tracer.h). Rays go to Embree as packets of kPacketSize lanes; the sampler's draws, the lights' samples and the
// BRDFs' samples and values are batch calls, whose long chains of arithmetic and cache misses overlap
// across lanes. Every lane takes the steps the reference takes, in its order, with the same draws, so
// each lane's radiance is the reference's bit for bit.
#include "renderer/integrator/panel_split.h"

#include <algorithm>

namespace glossy {

namespace {

static_assert(kWaveSize % kPacketSize == 0, "a wave is whole Embree packets");

// f(key, lanes, count) for each distinct key(i) among the lanes, its lanes in increasing order. A wave
// mostly has one BRDF and one or two lights, so this is one or two passes.
template <class Key, class F>
void forEachGroup(const Lanes& lanes, Key key, F&& f) {
  for (Lanes rest = lanes; rest.n > 0;) {
    const auto k0 = key(rest.lane[0]);
    Lanes group, others;
    for (const int i : rest) (key(i) == k0 ? group : others).add(i);
    f(k0, group.lane, group.n);
    rest = others;
  }
}

}  // namespace

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
      drawVertices(samplers, shading.lane, shading.n, DrawsUsed(context_, depth), draws_);
    sampleLights(depth, shading, shared);
    for (const int i : shading)
      if (stopping[i]) stops[i] = ObjectVertex{depth, path_[i], radiance[i], {hit_[i].mesh, point_[i], draws_[i], light_[i]}, samplers[i]};
    reflectAll(depth, reflecting, rays, alive, radiance);
  }
}

// light_ of the lanes: sampleLight, the j-th light samples of all lanes at a time, as batches per light and
// shadow-ray packets; distant lights' first samples from `shared` where it keeps them (deeper vertices,
// the only ones shared, take one).
void WaveTracer::sampleLights(int depth, const Lanes& lanes, SharedDraws* shared) {
  int most = 0;
  for (const int i : lanes) {
    light_[i].sets = draws_[i].lightSets;
    light_[i].count = lightDraws(draws_[i].lightSets);
    most = std::max(most, light_[i].count);
    from_[i] = receiver(point_[i]);
  }
  for (int j = 0; j < most; ++j) {
    Lanes sampled, drawn;
    for (const int i : lanes) {
      if (j >= light_[i].count) continue;
      light_[i].visible[j] = false;
      chosen_[i] = context_.lights.choose(draws_[i].lightChoice[j]);
      if (!chosen_[i]) continue;
      sampled.add(i);
      uLight_[i] = draws_[i].light[j];
      const Light* light = chosen_[i].light;
      const LightSample* kept =
          shared && light->distant() ? shared->find(depth, i, light, from_[i].normal, uLight_[i]) : nullptr;
      if (kept)
        lightSample_[i] = *kept;
      else
        drawn.add(i);
    }
    forEachGroup(drawn, [&](int i) { return chosen_[i].light; },
                 [&](const Light* light, const int* group, int n) { light->sample(from_, uLight_, group, n, lightSample_); });
    if (shared)
      for (const int i : drawn)
        if (chosen_[i].light->distant()) shared->keep(depth, i, chosen_[i].light, from_[i].normal, uLight_[i], lightSample_[i]);
    std::fill(shadowed_, shadowed_ + kWaveSize, false);
    for (const int i : sampled) {
      shadowed_[i] = toLight(point_[i], chosen_[i], lightSample_[i], light_[i].path[j]);
      shadow_[i] = light_[i].path[j].shadow;
    }
    for (int p = 0; p < kWaveSize; p += kPacketSize) context_.scene.bvh->occluded(shadowed_ + p, shadow_ + p, occluded_ + p);
    for (const int i : sampled) light_[i].visible[j] = shadowed_[i] && !occluded_[i];
  }
}

// reflect for the lanes: the BSDF samples and the BRDF's values toward the visible light samples, a batch
// per BRDF; then the paths go on (alive).
void WaveTracer::reflectAll(int depth, const Lanes& lanes, Ray* rays, bool* alive, Rgb* radiance) {
  forEachGroup(lanes, [&](int i) { return point_[i].brdf; },
               [&](const Brdf* brdf, const int* group, int n) { sampleBrdf(*brdf, group, n); });
  int most = 0;
  for (const int i : lanes) {
    most = std::max(most, point_[i].lightSamples);
    firstLight_[i] = lightOffset(light_[i].sets, point_[i].lightSamples);
  }
  // The light samples in the reference's order: the j-th of every lane's set, j = 0, 1, ….
  for (int j = 0; j < most; ++j) {
    Lanes lit;
    for (const int i : lanes)
      if (j < point_[i].lightSamples && light_[i].visible[firstLight_[i] + j]) lit.add(i);
    forEachGroup(lit, [&](int i) { return point_[i].brdf; },
                 [&](const Brdf* brdf, const int* group, int n) { evalBrdf(*brdf, j, group, n); });
    for (const int i : lit) {
      Rgb contribution;
      if (lightContribution(light_[i].path[firstLight_[i] + j], point_[i].lightSamples, value_[i], contribution))
        radiance[i] += path_[i].throughput * contribution;
    }
  }
  for (const int i : lanes)
    alive[i] = continuePath(depth, context_.settings, point_[i], bsdfSample_[i], draws_[i], path_[i], rays[i]);
}

// bsdfSample_ of the lanes: sampleBsdf, as one batch.
void WaveTracer::sampleBrdf(const Brdf& brdf, const int* lanes, int n) {
  if (context_.settings.cosineBrdfSampling) {
    for (int k = 0; k < n; ++k) bsdfSample_[lanes[k]] = sampleBsdf(context_.settings, point_[lanes[k]], draws_[lanes[k]]);
    return;
  }
  // Zeroed only because GCC cannot see that the batch reads the n lanes written.
  Vec3 wo[kWaveSize] = {};
  double uLobe[kWaveSize] = {};
  Vec2 u[kWaveSize] = {};
  BrdfSample samples[kWaveSize];
  for (int k = 0; k < n; ++k) {
    wo[k] = point_[lanes[k]].woLocal;
    uLobe[k] = draws_[lanes[k]].lobe;
    u[k] = draws_[lanes[k]].bsdf;
  }
  sampleBatch(brdf, wo, uLobe, u, samples, n);
  for (int k = 0; k < n; ++k) bsdfSample_[lanes[k]] = samples[k];
}

// value_ of the lanes: valueToward the j-th light samples of their sets, as one batch.
void WaveTracer::evalBrdf(const Brdf& brdf, int j, const int* lanes, int n) {
  if (context_.settings.cosineBrdfSampling) {
    for (int k = 0; k < n; ++k)
      value_[lanes[k]] = valueToward(context_.settings, point_[lanes[k]], light_[lanes[k]].path[firstLight_[lanes[k]] + j].wiLocal);
    return;
  }
  Vec3 wi[kWaveSize] = {}, wo[kWaveSize] = {};  // zeroed for GCC, as in sampleBrdf
  BrdfValue values[kWaveSize];
  for (int k = 0; k < n; ++k) {
    wi[k] = light_[lanes[k]].path[firstLight_[lanes[k]] + j].wiLocal;
    wo[k] = point_[lanes[k]].woLocal;
  }
  evalPdfBatch(brdf, wi, wo, values, n);
  for (int k = 0; k < n; ++k) value_[lanes[k]] = values[k];
}

}  // namespace glossy
