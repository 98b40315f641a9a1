#include "renderer/integrator/path_tracer.h"

#include "materials/core/frame.h"
#include "renderer/camera/camera_rays.h"
#include "renderer/sampling/sobol_sampler.h"
#include "renderer/util/progress.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

namespace glossy {

namespace {

constexpr int kTile = 16;

double powerHeuristic(double a, double b) {
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

double maxComponent(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

bool isFinite(const Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

// Leaving a surface: offset along the geometric normal, scaled to the position's float precision
// (Embree stores vertices as float).
Vec3 offsetOrigin(const Vec3& p, const Vec3& ng, const Vec3& dir) {
  const double eps = 1e-4 * (1.0 + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
  return p + ng * (glm::dot(dir, ng) > 0.0 ? eps : -eps);
}

class PathTracer {
 public:
  PathTracer(const RenderScene& scene, const RenderSettings& settings) : scene_(scene), settings_(settings) {
    const bool env = scene.environment != nullptr, area = scene.areaLights && !scene.areaLights->empty();
    pEnvironment_ = env ? (area ? 0.5 : 1.0) : 0.0;
  }

  Rgb trace(Ray ray, SobolSampler& sampler) const {
    Rgb radiance(0.0), throughput(1.0);
    double bsdfPdf = 0.0;  // solid-angle pdf of the BSDF sample that made `ray`; 0 for the camera ray
    for (int depth = 1;; ++depth) {
      Hit hit;
      if (!scene_.bvh->intersect(ray, hit)) {
        if (scene_.environment) {
          if (bsdfPdf > 0.0) {
            double pdfEnvironment;
            const Rgb le = scene_.environment->radianceAndPdf(ray.dir, pdfEnvironment);
            radiance += throughput * le * powerHeuristic(bsdfPdf, pEnvironment_ * pdfEnvironment);
          } else {
            radiance += throughput * scene_.environment->radiance(ray.dir);
          }
        }
        break;
      }
      const Vec3 wo = -ray.dir;
      const SceneMaterial* material = materialOf(hit.mesh);
      if (material && material->isEmissive()) {
        // Emitters are black bodies: they shine from their front face and reflect nothing.
        if (glm::dot(wo, hit.geometricNormal) > 0.0) {
          double w = 1.0;
          if (bsdfPdf > 0.0) {
            const double cosLight = glm::dot(wo, hit.geometricNormal);
            const double pdfLight = (1.0 - pEnvironment_) * scene_.areaLights->pdfArea() * hit.t * hit.t / cosLight;
            w = powerHeuristic(bsdfPdf, pdfLight);
          }
          radiance += throughput * material->emission * w;
        }
        break;
      }
      if (depth >= settings_.maxDepth) break;

      // Two-sided shading: face the normals toward the viewer. A shading normal that still faces away
      // would let light through the surface, so fall back to the geometric one there.
      Vec3 ng = hit.geometricNormal, ns = hit.shadingNormal;
      if (glm::dot(wo, ng) < 0.0) {
        ng = -ng;
        ns = -ns;
      }
      if (glm::dot(wo, ns) <= 0.0) ns = ng;
      const Frame frame(ns);
      const Vec3 woLocal = frame.toLocal(wo);
      if (woLocal.z <= 0.0) break;
      const Brdf& brdf = scene_.brdfOf(hit.mesh);

      radiance += throughput * sampleLight(hit.position, ng, frame, woLocal, brdf, sampler);

      const double uLobe = sampler.get1D();
      const BrdfSample s = sampleBrdf(brdf, woLocal, uLobe, sampler.get2D());
      if (!s.valid()) break;
      const Vec3 wi = frame.toWorld(s.L);
      if (glm::dot(wi, ng) <= 0.0) break;  // below the geometric surface: no leaking through it
      throughput *= s.weight;
      bsdfPdf = s.pdf;

      if (depth >= settings_.rouletteDepth) {
        const double survive = std::min(0.95, maxComponent(throughput));
        if (sampler.get1D() >= survive) break;
        throughput /= survive;
      }
      ray = Ray{offsetOrigin(hit.position, ng, wi), wi, 0.0, 1e30};
    }
    return radiance;
  }

 private:
  BrdfSample sampleBrdf(const Brdf& brdf, const Vec3& wo, double uLobe, Vec2 u) const {
    if (!settings_.cosineBrdfSampling) return sample(brdf, wo, uLobe, u);
    BrdfSample s;
    s.L = squareToCosineHemisphere(u);
    s.pdf = cosineHemispherePdf(s.L);
    if (s.pdf <= 0.0) return {};
    s.weight = eval(brdf, s.L, wo) * kPi;
    return s;
  }
  double pdfBrdf(const Brdf& brdf, const Vec3& wi, const Vec3& wo) const {
    return settings_.cosineBrdfSampling ? cosineHemispherePdf(wi) : pdf(brdf, wi, wo);
  }

  const SceneMaterial* materialOf(uint32_t mesh) const {
    const int m = scene_.description->meshes[mesh].material;
    return m < 0 ? nullptr : &scene_.description->materials[size_t(m)];
  }

  // One light sample, MIS-weighted against the BRDF's own sampling.
  Rgb sampleLight(const Vec3& p, const Vec3& ng, const Frame& frame, const Vec3& woLocal, const Brdf& brdf,
                  SobolSampler& sampler) const {
    // The area-light choice and triangle are drawn only when there is a choice to make.
    const double uChoice = pEnvironment_ > 0.0 && pEnvironment_ < 1.0 ? sampler.get1D() : 0.5;
    const Vec2 u = sampler.get2D();
    Vec3 wi;
    Rgb le;
    double pdfLight;
    Ray shadow;
    if (uChoice < pEnvironment_) {
      const Environment::Sample es = scene_.environment->sample(u);
      if (es.pdf <= 0.0) return Rgb(0.0);
      wi = es.dir;
      le = es.radiance;
      pdfLight = pEnvironment_ * es.pdf;
      shadow = Ray{offsetOrigin(p, ng, wi), wi, 0.0, 1e30};
    } else {
      const AreaLights::Sample as = scene_.areaLights->sample(sampler.get1D(), u);
      if (as.pdfArea <= 0.0) return Rgb(0.0);
      const Vec3 d = as.position - p;
      const double distance = glm::length(d);
      if (!(distance > 0.0)) return Rgb(0.0);
      wi = d / distance;
      const double cosLight = -glm::dot(wi, as.normal);
      if (cosLight <= 0.0) return Rgb(0.0);
      le = as.radiance;
      pdfLight = (1.0 - pEnvironment_) * as.pdfArea * distance * distance / cosLight;
      // The segment from the offset origin to the light, stopping short of the light's own surface by the
      // same margin the origin was moved by.
      const Vec3 origin = offsetOrigin(p, ng, wi);
      const Vec3 toLight = as.position - origin;
      const double length = glm::length(toLight);
      shadow = Ray{origin, toLight / length, 0.0, length - glm::length(origin - p)};
    }
    if (glm::dot(wi, ng) <= 0.0) return Rgb(0.0);
    const Vec3 wiLocal = frame.toLocal(wi);
    if (wiLocal.z <= 0.0) return Rgb(0.0);
    const Rgb f = eval(brdf, wiLocal, woLocal);
    if (maxComponent(f) <= 0.0) return Rgb(0.0);
    if (shadow.tfar <= 0.0 || scene_.bvh->occluded(shadow)) return Rgb(0.0);
    const double w = powerHeuristic(pdfLight, pdfBrdf(brdf, wiLocal, woLocal));
    return f * le * (wiLocal.z * w / pdfLight);
  }

  const RenderScene& scene_;
  const RenderSettings& settings_;
  double pEnvironment_ = 1.0;
};

}  // namespace

RgbImage render(const RenderScene& scene, const Camera& camera, const RenderSettings& settings, RenderStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  RgbImage image(settings.width, settings.height);
  const PathTracer tracer(scene, settings);
  std::atomic<uint64_t> dropped{0};
  const int tilesX = (settings.width + kTile - 1) / kTile, tilesY = (settings.height + kTile - 1) / kTile;
  Progress progress("render", size_t(tilesX) * size_t(tilesY));
  if (!settings.progress) progress.finish();

  auto renderTiles = [&](const tbb::blocked_range2d<int>& tiles) {
    SobolSampler sampler(settings.seed);
    uint64_t localDropped = 0;
    for (int ty = tiles.rows().begin(); ty < tiles.rows().end(); ++ty)
      for (int tx = tiles.cols().begin(); tx < tiles.cols().end(); ++tx) {
        for (int y = ty * kTile; y < std::min(settings.height, (ty + 1) * kTile); ++y)
          for (int x = tx * kTile; x < std::min(settings.width, (tx + 1) * kTile); ++x) {
            Rgb sum(0.0);
            for (int i = 0; i < settings.spp; ++i) {
              sampler.startPixelSample(uint32_t(x), uint32_t(y), uint32_t(settings.firstSample + i));
              const Vec2 jitter = sampler.get2D();
              const Rgb l = tracer.trace(cameraRay(camera, settings.width, settings.height, Vec2(x, y) + jitter), sampler);
              if (isFinite(l))
                sum += l;
              else
                ++localDropped;
            }
            const Rgb mean = sum / double(std::max(1, settings.spp));
            float* px = image.at(x, y);
            for (int c = 0; c < 3; ++c) px[c] = float(std::min(mean[c], double(std::numeric_limits<float>::max())));
          }
        progress.advance();
      }
    dropped += localDropped;
  };

  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] { tbb::parallel_for(tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1), renderTiles); });
  progress.finish();
  stats.droppedSamples = dropped.load();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

}  // namespace glossy
