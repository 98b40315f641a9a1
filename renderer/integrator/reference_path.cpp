// The reference path tracer, in pbrt-v4's order (PathIntegrator::Li and SampleLd): follow the camera ray
// to a surface; add what it sees of a light; at a reflecting vertex take one light sample (next-event
// estimation) and one BSDF sample, which continues the path; weigh each against the other's density by the
// power heuristic; end by Russian roulette or at the depth limit. Read from top to bottom, it is the whole
// algorithm: the lights and BRDFs it calls are the scene's, and tested on their own.
//
// Depth follows Mitsuba 3: maxDepth counts path segments, so 1 shows only directly visible emitters, 2 adds
// direct lighting, 3 one indirect bounce, and so on. Emitters are black bodies: they shine and reflect
// nothing, so a path that hits one ends there.
#include "renderer/integrator/reference_path.h"

#include "materials/core/frame.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace glossy {

namespace {

// The power heuristic for a sample drawn with density `drawn` that the other strategy draws with `other`.
double powerHeuristic(double drawn, double other) {
  const double a = drawn * drawn, b = other * other;
  return a + b > 0.0 ? a / (a + b) : 0.0;
}

// Where the path reflects: the hit with its normals turned toward the viewer (two-sided shading), the
// shading frame, and the direction back along the ray in that frame.
struct Vertex {
  Vec3 position{0.0}, ng{0.0};
  double margin = 0.0;
  Frame frame{Vec3(0.0, 0.0, 1.0)};
  Vec3 wo{0.0};  // local
  const Brdf* brdf = nullptr;
};

// False where the path cannot reflect: the viewer is below the shading frame's horizon.
bool vertexAt(const RenderScene& scene, const Ray& ray, const Hit& hit, Vertex& v) {
  const Vec3 wo = -ray.dir;
  Vec3 ng, ns;
  normalsFacing(hit, wo, ng, ns);
  v.position = hit.position;
  v.ng = ng;
  v.margin = hit.margin;
  v.frame = Frame(ns);
  v.wo = v.frame.toLocal(wo);
  v.brdf = &scene.brdfOf(hit.mesh);
  return v.wo.z > 0.0;
}

// The BRDF's value toward wi (local) and the density its sampling draws wi with: the model's own sampling,
// or the cosine lobe (RenderSettings::cosineBrdfSampling).
BrdfValue brdfToward(const RenderSettings& settings, const Vertex& v, const Vec3& wi) {
  if (settings.cosineBrdfSampling) return {eval(*v.brdf, wi, v.wo), cosineHemispherePdf(wi)};
  return evalPdf(*v.brdf, wi, v.wo);
}

BrdfSample sampleBrdf(const RenderSettings& settings, const Vertex& v, ReferenceRandom& random) {
  const double uLobe = random.next();
  const Vec2 u = random.next2D();
  if (settings.cosineBrdfSampling) return sampleCosineLobe(v.brdf->model(), v.wo, u);
  return sample(*v.brdf, v.wo, uLobe, u);
}

// Next-event estimation: a light chosen by power, a sample of it, its shadow ray, the BRDF's value, and
// the MIS weight against the BSDF sample that could have found the same light (1 for a delta light, which
// no BSDF sample finds). The radiance reflected toward the viewer, before the path's throughput.
Rgb directLight(const PathContext& context, const Vertex& v, ReferenceRandom& random) {
  const double uChoice = random.next();
  const Vec2 u = random.next2D();
  const ChosenLight chosen = context.lights.choose(uChoice);
  if (!chosen) return Rgb(0.0);
  const LightSample s = chosen.light->sample({v.position, v.frame.n}, u);
  if (!(s.pdf > 0.0) || glm::dot(s.wi, v.ng) <= 0.0) return Rgb(0.0);
  const Vec3 wi = v.frame.toLocal(s.wi);
  if (wi.z <= 0.0) return Rgb(0.0);

  Ray shadow = spawnRay(v.position, v.ng, v.margin, s.wi);
  if (!s.atInfinity) {
    // Toward the light's point, which the light has moved off its own surface by its margin. Where the two
    // margins overlap there is no room for an occluder between: the light is seen.
    const Vec3 d = s.target - shadow.origin;
    const double length = glm::length(d);
    if (!(glm::dot(d, s.wi) > 0.0 && length > 0.0)) shadow.tfar = -1.0;
    else shadow.dir = d / length, shadow.tfar = length;
  }
  if (shadow.tfar > 0.0 && context.scene.bvh->occluded(shadow)) return Rgb(0.0);

  const BrdfValue f = brdfToward(context.settings, v, wi);
  const double lightPdf = chosen.probability * s.pdf;
  const double weight = s.delta ? 1.0 : powerHeuristic(lightPdf, f.pdf);
  return f.f * s.radiance * (wi.z * weight / lightPdf);
}

// The weight of emission a BSDF sample found against the light samples that could have found it; the
// camera ray's (bsdfPdf 0) is not weighed.
double emissionWeight(double bsdfPdf, double lightPdf) { return bsdfPdf > 0.0 ? powerHeuristic(bsdfPdf, lightPdf) : 1.0; }

}  // namespace

Rgb referenceRadiance(const PathContext& context, Ray ray, ReferenceRandom& random) {
  const RenderSettings& settings = context.settings;
  Rgb radiance(0.0), throughput(1.0);
  Receiver from{ray.origin, Vec3(0.0)};  // the vertex the ray left: first the camera, which has no surface
  double bsdfPdf = 0.0;                  // of the BSDF sample that made the ray
  for (int depth = 1;; ++depth) {
    // The ray's segment: it leaves the scene and sees the distant lights, or it ends on a surface.
    Hit hit;
    if (!context.scene.bvh->intersect(ray, hit)) {
      for (const ChosenLight& distant : context.lights.distant()) {
        double pdf = 0.0;
        const Rgb arriving = distant.light->arriving(ray.dir, from, pdf);
        radiance += throughput * arriving * emissionWeight(bsdfPdf, distant.probability * pdf);
      }
      return radiance;
    }
    if (const ChosenLight light = context.lights.at(hit)) {
      double pdf = 0.0;
      const Rgb emitted = light.light->emitted(hit, from, pdf);
      return radiance + throughput * emitted * emissionWeight(bsdfPdf, light.probability * pdf);
    }
    if (depth >= settings.maxDepth) return radiance;
    Vertex v;
    if (!vertexAt(context.scene, ray, hit, v)) return radiance;

    // The vertex's light sample, then its BSDF sample, which continues the path.
    radiance += throughput * directLight(context, v, random);
    const BrdfSample s = sampleBrdf(settings, v, random);
    if (!s.valid()) return radiance;
    const Vec3 wi = v.frame.toWorld(s.L);
    if (glm::dot(wi, v.ng) <= 0.0) return radiance;  // below the geometric surface: no leaking through it
    throughput *= s.weight;
    bsdfPdf = s.pdf;
    from = {v.position, v.frame.n};

    if (depth >= settings.rouletteDepth) {
      const double survive = std::min(0.95, std::max({throughput.r, throughput.g, throughput.b}));
      if (random.next() >= survive) return radiance;
      throughput /= survive;
    }
    ray = spawnRay(v.position, v.ng, v.margin, wi);
  }
}

}  // namespace glossy
