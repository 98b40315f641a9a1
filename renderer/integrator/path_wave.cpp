// The wave's path tracer, as pbrt-v4's PathIntegrator::Li, for kWaveSize paths at once (path_vertex.h).
// Unidirectional path tracing with next-event estimation (direct_light.h: at a
// camera path's first vertex as many light samples as its BRDF takes, light_count.h, one at each deeper
// one, each of a light chosen by power) combined with BSDF sampling by multiple importance sampling (power
// heuristic with sample counts: a first vertex takes as many BSDF samples as its BRDF takes, of which the
// first continues the path), and Russian roulette. Tests hold it to the reference path tracer's expectation
// (reference_path.cpp), pixel block by pixel block.
//
// Depth follows Mitsuba 3: maxDepth counts path segments, so 1 shows only directly visible emitters, 2 adds
// direct lighting, 3 one indirect bounce, and so on.
#include "renderer/integrator/path_vertex.h"
#include "renderer/integrator/shared_draws.h"

namespace glossy {

static_assert(kWaveSize % kPacketSize == 0, "the scene traces a wave's rays as whole packets");

Lanes Paths::next(int depth, const Lanes& lanes, const Ray* rays, CmjSampler* samplers, Rgb* radiance, SharedDraws* shared) {
  bool active[kWaveSize] = {};
  for (const int i : lanes) active[i] = true;
  context_.scene.bvh->intersect(active, rays, hit, found_, kWaveSize);
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
  for (const int i : shading) draws[i].lightCount = uint32_t(context_.lightSamplesAt(hit[i].mesh, depth));
  for (const int i : shading) draws[i].bsdfCount = uint32_t(context_.bsdfSamplesAt(hit[i].mesh, depth));
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

Lanes Paths::reflect(int depth, const Lanes& lanes, Ray* rays, Rgb* radiance) {
  // The direct light, weighed by the BRDFs; then the BSDF samples, which continue the paths.
  for (const int i : lanes) throughput_[i] = path[i].throughput;
  direct_.add(context_.settings, lanes, point, light, throughput_, radiance);
  for (const int i : lanes) takeBsdfDraw(draws[i], 0, draws[i]);
  sampleBsdfs(context_.settings, lanes, point, draws, bsdf_);
  Lanes more;
  for (const int i : lanes)
    if (point[i].bsdfSamples > 1) more.add(i);
  if (more.n > 0) addOtherBsdfSamples(depth, more, radiance);
  Lanes alive;
  for (const int i : lanes)
    if (continuePath(depth, context_.settings, point[i], bsdf_[i], draws[i], path[i], rays[i])) alive.add(i);
  return alive;
}

void Paths::addOtherBsdfSamples(int depth, const Lanes& lanes, Rgb* radiance) {
  // Where no ray can hit a light, what a further sample finds is the distant lights' emission if its ray
  // leaves the scene, else nothing: resample them (below) rather than trace each. Resampling hashes its
  // uniforms from the roulette draw, which a vertex that plays no roulette leaves unused (vertex_draws.h).
  const bool resample = !context_.lights.onSurfaces() && depth < context_.settings.rouletteDepth;
  int most = 1;
  for (const int i : lanes) {
    most = std::max(most, point[i].bsdfSamples);
    PathState& p = otherPath_[i];  // what the samples share: their vertex and its counts
    p.lightSamples = point[i].lightSamples;
    p.bsdfSamples = point[i].bsdfSamples;
    p.from = receiver(point[i]);
    from_[i] = p.from;
    resampled_[i] = Resampled(draws[i].roulette);
  }
  for (int j = 1; j < most; ++j) {
    Lanes sampled;
    for (const int i : lanes)
      if (j < point[i].bsdfSamples) {
        takeBsdfDraw(draws[i], j, otherDraws_[i]);
        sampled.add(i);
      }
    sampleBsdfs(context_.settings, sampled, point, otherDraws_, other_);
    Lanes valid;
    for (const int i : sampled) {
      const BrdfSample& s = other_[i];
      if (!s.valid()) continue;
      direction_[i] = point[i].frame.toWorld(s.L);
      if (glm::dot(direction_[i], point[i].ng) <= 0.0) continue;
      otherPath_[i].throughput = path[i].throughput * s.weight;
      otherPath_[i].bsdfPdf = s.pdf;
      valid.add(i);
    }
    if (resample) {
      for (const int i : valid) candidate_[i] = Rgb(0.0);
      addDistantEmission(valid, otherPath_, candidate_);
      for (const int i : valid) choose(i, j);
      continue;
    }
    bool active[kWaveSize] = {};
    for (const int i : valid) {
      otherRays_[i] = spawnRay(point[i].position, point[i].ng, point[i].margin, direction_[i]);
      active[i] = true;
    }
    context_.scene.bvh->intersect(active, otherRays_, otherHit_, otherFound_, kWaveSize);
    Lanes escaped;
    for (const int i : valid) {
      if (!otherFound_[i]) {
        escaped.add(i);
      } else if (const ChosenLight light = context_.lights.at(otherHit_[i])) {
        double pdf = 0.0;
        const Rgb emitted = light.light->emitted(otherHit_[i], otherPath_[i].from, pdf);
        addEmission(otherPath_[i], emitted, light.probability * pdf, radiance[i]);
      }
    }
    addDistantEmission(escaped, otherPath_, radiance);
  }
  if (resample) addChosenSamples(lanes, radiance);
}

void Paths::addChosenSamples(const Lanes& lanes, Rgb* radiance) {
  // Each channel's chosen sample's ray, traced, once where channels chose the same sample: the channel's
  // emission, Σ c over its probability c_j / Σ c of being chosen times c_j, arrives if the ray leaves the
  // scene. Where nothing blocks them, exactly the samples' sum.
  bool visible[kWaveSize][3] = {};
  for (int c = 0; c < 3; ++c) {
    Lanes traced;
    bool active[kWaveSize] = {}, blocked[kWaveSize] = {};
    for (const int i : lanes) {
      const Resampled& r = resampled_[i];
      if (!(r.sum[c] > 0.0)) continue;
      const int same = c > 0 && r.chosen[c - 1] == r.chosen[c] ? c - 1 : c > 1 && r.chosen[0] == r.chosen[c] ? 0 : -1;
      if (same >= 0) {
        visible[i][c] = visible[i][same];
        continue;
      }
      otherRays_[i] = spawnRay(point[i].position, point[i].ng, point[i].margin, r.direction[c]);
      active[i] = true;
      traced.add(i);
    }
    context_.scene.bvh->occluded(active, otherRays_, blocked, kWaveSize);
    for (const int i : traced) visible[i][c] = !blocked[i];
  }
  for (const int i : lanes)
    for (int c = 0; c < 3; ++c)
      if (visible[i][c]) radiance[i][c] += resampled_[i].sum[c];
}

void Paths::choose(int i, int j) {
  // Weighted reservoir sampling in each channel: candidate j replaces the one kept with probability
  // c / (the channel's sum so far), so that in the end each is kept with c_j / Σ c. The candidate's
  // uniform, hashed from the vertex's draw and j, is the same in every channel, so where their candidates
  // are in proportion the channels keep the same one.
  Resampled& r = resampled_[i];
  const double u = cmj_detail::toUnit(cmj_detail::hash(r.seed, uint32_t(j)));
  for (int c = 0; c < 3; ++c) {
    const double w = candidate_[i][c];
    if (!(w > 0.0)) continue;
    r.sum[c] += w;
    if (u * r.sum[c] < w) {
      r.chosen[c] = j;
      r.direction[c] = direction_[i];
    }
  }
}

void Paths::addDistantEmission(const Lanes& escaped, const PathState* paths, Rgb* radiance) {
  for (const ChosenLight& distant : context_.lights.distant()) {
    distant.light->arriving(direction_, from_, escaped.lane, escaped.n, arriving_, pdf_);
    for (const int i : escaped) addEmission(paths[i], arriving_[i], distant.probability * pdf_[i], radiance[i]);
  }
}

}  // namespace glossy
