// The wave: a path's steps from one vertex to the next, taken for kWaveSize paths (lanes.h) at once before
// the next step, each step one batch (Embree packets, the sampler's draws, the lights' samples, the BRDFs'
// samples and values) whose long chains of arithmetic and cache misses overlap across lanes. The steps are
// in path_wave.cpp; the same algorithm for one path in plain code is the reference (reference_path.cpp).
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
  int bsdfSamples = 1;   // likewise
  Receiver from;         // the vertex the ray left (the light densities of MIS are seen from it)
};

// Emission found by the path's ray (from a light it hit or a distant light it escaped to), weighted
// against the light samples that could have found it, added to radiance with the path's throughput:
// lightPdf is one's density, its light's choice included, and the vertex took path.lightSamples of them
// and path.bsdfSamples BSDF samples, of which this is one (the power heuristic with sample counts). A
// camera ray's is unweighted.
inline void addEmission(const PathState& path, const Rgb& emitted, double lightPdf, Rgb& radiance) {
  if (!(path.bsdfPdf > 0.0)) {
    radiance += path.throughput * emitted;
    return;
  }
  const int n = path.bsdfSamples;
  radiance += path.throughput * emitted * (powerHeuristic(n * path.bsdfPdf, path.lightSamples * lightPdf) / n);
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
  sp.bsdfSamples = context.bsdfSamplesAt(hit.mesh, depth);
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
  path.bsdfSamples = sp.bsdfSamples;
  path.from = receiver(sp);
  if (depth >= settings.rouletteDepth) {
    const double survive = std::min(0.95, maxComponent(path.throughput));
    if (u.roulette >= survive) return false;
    path.throughput /= survive;
  }
  ray = spawnRay(sp.position, sp.ng, sp.margin, wi);
  return true;
}

class SharedDraws;

// The paths of a wave, up to kWaveSize lanes, and their state, advanced together a vertex at a time. Made
// once per thread and reused, as a wave's state is too large to clear per wave.
// The lanes index the caller's rays, samplers (past the film position) and radiance, as theirs.
class Paths {
 public:
  explicit Paths(const PathContext& context) : context_(context) {}

  // From a vertex at `depth` on, next then reflect until the lanes' paths end (pbrt-v4's
  // PathIntegrator::Li for each): stop(depth, lanes) returns those of the lanes at their vertices that go on
  // (the panel split parks the others there, panel_split.h). Their draws come from shared where given.
  template <class Stop>
  void walk(int depth, Lanes lanes, Ray* rays, CmjSampler* samplers, Rgb* radiance, SharedDraws* shared, Stop&& stop) {
    for (; lanes.n > 0; ++depth)
      lanes = reflect(depth, stop(depth, next(depth, lanes, rays, samplers, radiance, shared)), rays, radiance);
  }
  // The lanes' rays, their depth-th segments, to the next reflecting vertices, adding the emission they find
  // on the way (a light hit, the distant lights when they leave the scene): the lanes that reflect there,
  // with each vertex's point, draws and light samples with their shadow rays' verdicts.
  Lanes next(int depth, const Lanes& lanes, const Ray* rays, CmjSampler* samplers, Rgb* radiance, SharedDraws* shared);
  // The vertices' BRDFs act: the direct light, then their samples continue the paths (rays). The lanes whose
  // paths go on.
  Lanes reflect(int depth, const Lanes& lanes, Ray* rays, Rgb* radiance);
  // The lanes' vertices' BSDF samples after the first (ShadingPoint::bsdfSamples), none of which continues:
  // each adds the emission it finds (a light hit, the distant lights when it leaves the scene). Each is
  // traced to what it finds; where no ray can hit a light, one of them is chosen, in each colour channel,
  // in proportion to the emission it would find there if nothing were in the way (resampled importance
  // sampling, Talbot et al. 2005), and only its ray is traced: that emission, over its probability of
  // being chosen, if the ray leaves the scene. Unbiased, as the choice only weighs the sum's terms; where
  // nothing blocks the samples, as on a convex object under a map, exactly what tracing them all gives,
  // colour included, for one ray (more only where the channels chose different samples).
  void addOtherBsdfSamples(int depth, const Lanes& lanes, Rgb* radiance);
  // Offers lane i's resampling its j-th sample's candidate_, found along direction_[i].
  void choose(int i, int j);
  // The resampled lanes' chosen samples, each channel's ray traced: their emission where it is unblocked.
  void addChosenSamples(const Lanes& lanes, Rgb* radiance);
  // The distant lights' emission for the escaped lanes, whose rays' directions and vertices are in
  // direction_ and from_, weighted as paths[i]'s (addEmission), added to radiance[i].
  void addDistantEmission(const Lanes& escaped, const PathState* paths, Rgb* radiance);

  // Each lane's path, its last hit, and its vertex there before the BRDF acts.
  PathState path[kWaveSize];
  Hit hit[kWaveSize];
  ShadingPoint point[kWaveSize];
  VertexDraws draws[kWaveSize];
  VertexLight light[kWaveSize];

 private:
  const PathContext& context_;
  bool found_[kWaveSize];
  Vec3 direction_[kWaveSize];  // of the rays that left the scene (addOtherBsdfSamples: of its samples)
  Receiver from_[kWaveSize];   // their vertices
  Rgb arriving_[kWaveSize], throughput_[kWaveSize];
  double pdf_[kWaveSize];
  DirectLight direct_;
  BrdfSample bsdf_[kWaveSize];
  // addOtherBsdfSamples' scratch: each lane's sample, as the draws, the ray and hit and the path it makes
  // (its direction in direction_).
  VertexDraws otherDraws_[kWaveSize];
  BrdfSample other_[kWaveSize];
  Ray otherRays_[kWaveSize];
  Hit otherHit_[kWaveSize];
  bool otherFound_[kWaveSize];
  PathState otherPath_[kWaveSize];
  // The resampling's: a candidate's emission; the seed of the candidates' uniforms, and per channel the
  // candidates' sum and the sample kept with its direction.
  struct Resampled {
    Resampled() = default;
    explicit Resampled(double u) : seed(uint32_t(u * 0x1p32)) {}
    uint32_t seed = 0;
    double sum[3] = {};
    int chosen[3] = {-1, -1, -1};
    Vec3 direction[3];
  };
  Rgb candidate_[kWaveSize];
  Resampled resampled_[kWaveSize];
};

}  // namespace glossy
