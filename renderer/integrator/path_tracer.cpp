#include "renderer/integrator/path_tracer.h"

#include "materials/core/frame.h"
#include "renderer/camera/camera_rays.h"
#include "renderer/sampling/cmj_sampler.h"
#include "renderer/util/progress.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace glossy {

namespace {

constexpr int kTile = 16;
// Paths traced together (kWaveSize / kPacketSize Embree packets): long enough for the environment's cache
// misses to overlap, short enough for a wave's state to stay in L1/L2.
constexpr int kWaveSize = 128;
static_assert(kWaveSize % kPacketSize == 0, "a wave is whole Embree packets");
static_assert(kWaveSize <= Environment::kMaxBatch, "a wave's environment lookups are one batch");
// 0, 1, …, kWaveSize − 1: every lane of a wave, for the batch draws.
constexpr std::array<int, kWaveSize> kLanes = [] {
  std::array<int, kWaveSize> lanes{};
  for (int i = 0; i < kWaveSize; ++i) lanes[i] = i;
  return lanes;
}();

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

  // Where a path meets a reflecting surface: what its light sample and BSDF sample need.
  struct ShadingPoint {
    Vec3 position{0.0}, ng{0.0};  // ng faces the viewer
    Frame frame{Vec3(0.0, 0.0, 1.0)};
    Vec3 woLocal{0.0};
    const Brdf* brdf = nullptr;
  };

  // A light sample seen from a shading point.
  struct LightSample {
    Vec3 wiLocal{0.0};  // toward the light, in the shading frame
    Rgb radiance{0.0};
    double pdf = 0.0;   // solid angle, the light's choice included
  };

  // What a wave's lanes carry between the stages of a vertex. Built once per task and reused: zeroing
  // it per wave would cost more than some of the stages.
  struct Workspace {
    Rgb throughput[kWaveSize];
    double bsdfPdf[kWaveSize];  // solid-angle pdf of the BSDF sample that made the ray; 0 for camera rays
    Hit hits[kWaveSize];
    bool found[kWaveSize], escaped[kWaveSize], shading[kWaveSize], toEnvironment[kWaveSize];
    ShadingPoint points[kWaveSize];
    Vec2 uLight[kWaveSize];
    Environment::Sample lightSamples[kWaveSize];
    Vec3 escapedDirs[kWaveSize];
    Environment::RadianceBatch skyLookups;
    Environment::SampleBatch lightLookups;
    int shadingLane[kWaveSize], areaLane[kWaveSize];  // the lanes that shade, and that sample an area light
    double uChoice[kWaveSize], uTriangle[kWaveSize];
    Rgb skyRadiance[kWaveSize];
    double skyPdf[kWaveSize];
    Rgb vertexThroughput[kWaveSize];  // the throughput at the vertex, for its light sample
    double uLobe[kWaveSize];
    Vec2 uBsdf[kWaveSize];
    BrdfSample bsdfSamples[kWaveSize];
    LightSample lights[kWaveSize];  // the light sample at the vertex, before its BRDF value
    bool lit[kWaveSize];            // lights[i] needs its BRDF value
    BrdfValue lightValues[kWaveSize];
    Ray shadows[kWaveSize];
    bool shadowed[kWaveSize], occluded[kWaveSize];
    Rgb unoccluded[kWaveSize];  // what each shadow ray brings if it reaches its light
  };

  // The paths of up to kWaveSize samples, traced together in stages. Each segment's rays go to Embree as
  // packet queries of kPacketSize lanes, each vertex's shadow rays likewise, and the environment is looked
  // up and sampled for all lanes at once: a lookup is a chain of dependent loads that mostly miss the
  // cache, and across a whole wave each step's misses overlap instead of queueing. The sampler's draws and
  // the BRDFs' samples and values are batches too, whose long chains of arithmetic overlap across lanes
  // (and vectorise, where a model has batch forms). Every lane has its own sampler and draws exactly what a
  // lone path would (the same dimensions in the same order), so the image does not depend on how samples
  // are grouped.
  void traceWave(Ray* rays, CmjSampler* samplers, bool* alive, Rgb* radiance, Workspace& w) const {
    for (int i = 0; i < kWaveSize; ++i) {
      radiance[i] = Rgb(0.0);
      w.throughput[i] = Rgb(1.0);
      w.bsdfPdf[i] = 0.0;
    }

    for (int depth = 1;; ++depth) {
      if (std::none_of(alive, alive + kWaveSize, [](bool a) { return a; })) break;
      for (int p = 0; p < kWaveSize; p += kPacketSize)
        scene_.bvh->intersect(alive + p, rays + p, w.hits + p, w.found + p);

      // Each environment lookup is begun (its cells found and prefetched) well before it is ended (read),
      // with other lanes' work in between, so that its cache misses overlap that work. Each lane still
      // draws its dimensions in the order a lone path would.
      // Rays that left the scene see the environment, MIS-weighted unless they are camera rays.
      const Environment* env = scene_.environment;
      for (int i = 0; i < kWaveSize; ++i) {
        w.escaped[i] = alive[i] && !w.found[i] && env;
        if (w.escaped[i]) w.escapedDirs[i] = rays[i].dir;
      }
      if (env) env->beginRadianceAndPdf(w.escaped, w.escapedDirs, kWaveSize, w.skyLookups);
      int shadingLanes = 0;
      for (int i = 0; i < kWaveSize; ++i) {
        w.shading[i] = alive[i] && w.found[i] &&
                       surface(depth, rays[i], w.hits[i], w.throughput[i], w.bsdfPdf[i], radiance[i], w.points[i]);
        alive[i] = w.shading[i];
        w.shadowed[i] = w.toEnvironment[i] = false;
        if (w.shading[i]) w.shadingLane[shadingLanes++] = i;
      }
      // The light samples' draws, for the shading lanes at once (batch draws: the values a lane drawing
      // alone gets, in the same order). The area-light choice and triangle are drawn only when there is a
      // choice to make.
      const bool choice = pEnvironment_ > 0.0 && pEnvironment_ < 1.0;
      if (choice) CmjSampler::get1D(samplers, w.shadingLane, shadingLanes, w.uChoice);
      CmjSampler::get2D(samplers, w.shadingLane, shadingLanes, w.uLight);
      int areaLanes = 0;
      for (int k = 0; k < shadingLanes; ++k) {
        const int i = w.shadingLane[k];
        w.toEnvironment[i] = (choice ? w.uChoice[i] : 0.5) < pEnvironment_;
        if (!w.toEnvironment[i]) w.areaLane[areaLanes++] = i;
      }
      CmjSampler::get1D(samplers, w.areaLane, areaLanes, w.uTriangle);
      if (env) {
        env->beginSample(w.toEnvironment, w.uLight, kWaveSize, w.lightLookups);
        env->endRadianceAndPdf(w.skyLookups, w.skyRadiance, w.skyPdf);
      }
      for (int i = 0; i < kWaveSize; ++i)
        if (w.escaped[i])
          radiance[i] += w.throughput[i] * w.skyRadiance[i] *
                         (w.bsdfPdf[i] > 0.0 ? powerHeuristic(w.bsdfPdf[i], pEnvironment_ * w.skyPdf[i]) : 1.0);
      // The BSDF samples, while the light samples' texels arrive: each lane draws its dimensions, then the
      // lanes of each BRDF are sampled as one batch.
      for (int i = 0; i < kWaveSize; ++i) w.vertexThroughput[i] = w.throughput[i];
      CmjSampler::get1D(samplers, w.shadingLane, shadingLanes, w.uLobe);
      CmjSampler::get2D(samplers, w.shadingLane, shadingLanes, w.uBsdf);
      forEachBrdf(w.shading, w.points, [&](const Brdf& brdf, const int* lanes, int n) { sampleBrdfs(brdf, lanes, n, w); });
      for (int i = 0; i < kWaveSize; ++i) {
        if (!w.shading[i]) continue;
        alive[i] = continuePath(depth, w.points[i], w.bsdfSamples[i], samplers[i], w.throughput[i], w.bsdfPdf[i], rays[i]);
      }
      if (env) env->endSample(w.lightLookups, w.lightSamples);
      // The light samples: their geometry lane by lane, their BRDF values per BRDF as one batch, then MIS.
      for (int i = 0; i < kWaveSize; ++i) {
        w.lit[i] = false;
        if (!w.shading[i]) continue;
        const ShadingPoint& sp = w.points[i];
        w.lit[i] = w.toEnvironment[i] ? lightFromEnvironment(sp, w.lightSamples[i], w.shadows[i], w.lights[i])
                                      : lightFromArea(sp, w.uTriangle[i], w.uLight[i], w.shadows[i], w.lights[i]);
      }
      forEachBrdf(w.lit, w.points, [&](const Brdf& brdf, const int* lanes, int n) { evalBrdfs(brdf, lanes, n, w); });
      for (int i = 0; i < kWaveSize; ++i) {
        w.shadowed[i] = w.lit[i] && lightContribution(w.lights[i], w.lightValues[i], w.unoccluded[i]);
        if (w.shadowed[i]) w.unoccluded[i] *= w.vertexThroughput[i];
      }
      for (int p = 0; p < kWaveSize; p += kPacketSize)
        scene_.bvh->occluded(w.shadowed + p, w.shadows + p, w.occluded + p);
      for (int i = 0; i < kWaveSize; ++i)
        if (w.shadowed[i] && !w.occluded[i]) radiance[i] += w.unoccluded[i];
    }
  }

 private:
  // The ray's hit: its emission if it is a light (ending the path), else the shading point. False ends
  // the path.
  bool surface(int depth, const Ray& ray, const Hit& hit, const Rgb& throughput, double bsdfPdf, Rgb& radiance,
               ShadingPoint& sp) const {
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
      return false;
    }
    if (depth >= settings_.maxDepth) return false;

    // Two-sided shading: face the normals toward the viewer. A shading normal that still faces away
    // would let light through the surface, so fall back to the geometric one there.
    Vec3 ng = hit.geometricNormal, ns = hit.shadingNormal;
    if (glm::dot(wo, ng) < 0.0) {
      ng = -ng;
      ns = -ns;
    }
    if (glm::dot(wo, ns) <= 0.0) ns = ng;
    sp.position = hit.position;
    sp.ng = ng;
    sp.frame = Frame(ns);
    sp.woLocal = sp.frame.toLocal(wo);
    if (sp.woLocal.z <= 0.0) return false;
    sp.brdf = &scene_.brdfOf(hit.mesh);
    return true;
  }

  // The lanes of a wave with want[i], grouped by their shading point's BRDF: f(brdf, lanes, n) for each
  // group, the lanes in increasing order. A wave almost always has one BRDF, so this is one pass.
  template <class F>
  static void forEachBrdf(const bool* want, const ShadingPoint* points, F&& f) {
    bool pending[kWaveSize];
    std::copy(want, want + kWaveSize, pending);
    int lanes[kWaveSize];
    for (int first = 0; first < kWaveSize; ++first) {
      if (!pending[first]) continue;
      const Brdf* brdf = points[first].brdf;
      int n = 0;
      for (int i = first; i < kWaveSize; ++i)
        if (pending[i] && points[i].brdf == brdf) {
          lanes[n++] = i;
          pending[i] = false;
        }
      f(*brdf, lanes, n);
    }
  }

  // w.bsdfSamples of the lanes, from their shading points and draws.
  void sampleBrdfs(const Brdf& brdf, const int* lanes, int n, Workspace& w) const {
    Vec3 wo[kWaveSize];
    double uLobe[kWaveSize];
    Vec2 u[kWaveSize];
    BrdfSample samples[kWaveSize];
    for (int k = 0; k < n; ++k) {
      wo[k] = w.points[lanes[k]].woLocal;
      uLobe[k] = w.uLobe[lanes[k]];
      u[k] = w.uBsdf[lanes[k]];
    }
    if (settings_.cosineBrdfSampling) {
      for (int k = 0; k < n; ++k) samples[k] = sampleCosine(brdf, wo[k], u[k]);
    } else {
      sampleBatch(brdf, wo, uLobe, u, samples, n);
    }
    for (int k = 0; k < n; ++k) w.bsdfSamples[lanes[k]] = samples[k];
  }

  // w.lightValues of the lanes: the BRDF and its sampling density toward each light sample.
  void evalBrdfs(const Brdf& brdf, const int* lanes, int n, Workspace& w) const {
    Vec3 wi[kWaveSize], wo[kWaveSize];
    BrdfValue values[kWaveSize];
    for (int k = 0; k < n; ++k) {
      wi[k] = w.lights[lanes[k]].wiLocal;
      wo[k] = w.points[lanes[k]].woLocal;
    }
    if (settings_.cosineBrdfSampling) {
      for (int k = 0; k < n; ++k) values[k] = {eval(brdf, wi[k], wo[k]), cosineHemispherePdf(wi[k])};
    } else {
      evalPdfBatch(brdf, wi, wo, values, n);
    }
    for (int k = 0; k < n; ++k) w.lightValues[lanes[k]] = values[k];
  }

  // The BSDF sample s that continues the path: the next ray, the throughput and pdf it carries. False ends
  // the path.
  bool continuePath(int depth, const ShadingPoint& sp, const BrdfSample& s, CmjSampler& sampler, Rgb& throughput,
                    double& bsdfPdf, Ray& ray) const {
    if (!s.valid()) return false;
    const Vec3 wi = sp.frame.toWorld(s.L);
    if (glm::dot(wi, sp.ng) <= 0.0) return false;  // below the geometric surface: no leaking through it
    throughput *= s.weight;
    bsdfPdf = s.pdf;

    if (depth >= settings_.rouletteDepth) {
      const double survive = std::min(0.95, maxComponent(throughput));
      if (sampler.get1D() >= survive) return false;
      throughput /= survive;
    }
    ray = Ray{offsetOrigin(sp.position, sp.ng, wi), wi, 0.0, 1e30};
    return true;
  }

  static BrdfSample sampleCosine(const Brdf& brdf, const Vec3& wo, Vec2 u) {
    BrdfSample s;
    s.L = squareToCosineHemisphere(u);
    s.pdf = cosineHemispherePdf(s.L);
    if (s.pdf <= 0.0) return {};
    s.weight = eval(brdf, s.L, wo) * kPi;
    return s;
  }

  const SceneMaterial* materialOf(uint32_t mesh) const {
    const int m = scene_.description->meshes[mesh].material;
    return m < 0 ? nullptr : &scene_.description->materials[size_t(m)];
  }

  // A light sample: the shadow ray to trace and what the light brings along it, before the BRDF's value
  // toward it (evalBrdfs) and the MIS weight (lightContribution). False when there is nothing to trace.
  bool lightFromEnvironment(const ShadingPoint& sp, const Environment::Sample& es, Ray& shadow, LightSample& light) const {
    if (es.pdf <= 0.0) return false;
    shadow = Ray{offsetOrigin(sp.position, sp.ng, es.dir), es.dir, 0.0, 1e30};
    return prepareLight(sp, es.dir, es.radiance, pEnvironment_ * es.pdf, shadow, light);
  }

  bool lightFromArea(const ShadingPoint& sp, double uTriangle, Vec2 u, Ray& shadow, LightSample& light) const {
    const AreaLights::Sample as = scene_.areaLights->sample(uTriangle, u);
    if (as.pdfArea <= 0.0) return false;
    const Vec3 d = as.position - sp.position;
    const double distance = glm::length(d);
    if (!(distance > 0.0)) return false;
    const Vec3 wi = d / distance;
    const double cosLight = -glm::dot(wi, as.normal);
    if (cosLight <= 0.0) return false;
    const double pdfLight = (1.0 - pEnvironment_) * as.pdfArea * distance * distance / cosLight;
    // The segment from the offset origin to the light, stopping short of the light's own surface by the
    // same margin the origin was moved by.
    const Vec3 origin = offsetOrigin(sp.position, sp.ng, wi);
    const Vec3 toLight = as.position - origin;
    const double length = glm::length(toLight);
    shadow = Ray{origin, toLight / length, 0.0, length - glm::length(origin - sp.position)};
    return prepareLight(sp, wi, as.radiance, pdfLight, shadow, light);
  }

  static bool prepareLight(const ShadingPoint& sp, const Vec3& wi, const Rgb& le, double pdfLight, const Ray& shadow,
                           LightSample& light) {
    if (glm::dot(wi, sp.ng) <= 0.0) return false;
    light.wiLocal = sp.frame.toLocal(wi);
    if (light.wiLocal.z <= 0.0) return false;
    if (shadow.tfar <= 0.0) return false;
    light.radiance = le;
    light.pdf = pdfLight;
    return true;
  }

  // What the light sample brings if nothing blocks it, MIS-weighted against the BRDF's own sampling
  // (before the path's throughput). False when that is nothing.
  static bool lightContribution(const LightSample& light, const BrdfValue& value, Rgb& contribution) {
    if (maxComponent(value.f) <= 0.0) return false;
    const double w = powerHeuristic(light.pdf, value.pdf);
    contribution = value.f * light.radiance * (light.wiLocal.z * w / light.pdf);
    return true;
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

  const CameraRays cameraRays(camera, settings.width, settings.height);
  const CmjPattern pattern(uint32_t(std::max(1, settings.spp)));
  auto renderTiles = [&](const tbb::blocked_range2d<int>& tiles) {
    uint64_t localDropped = 0;
    CmjSampler samplers[kWaveSize];
    Ray rays[kWaveSize];
    bool alive[kWaveSize];
    Rgb radiance[kWaveSize];
    int lanePixel[kWaveSize];  // which of the tile's pixels each lane samples
    Vec2 film[kWaveSize];
    auto workspace = std::make_unique<PathTracer::Workspace>();
    std::vector<CmjPixel> pixels;
    std::vector<Rgb> sums;
    pixels.reserve(size_t(kTile) * kTile);
    for (int ty = tiles.rows().begin(); ty < tiles.rows().end(); ++ty)
      for (int tx = tiles.cols().begin(); tx < tiles.cols().end(); ++tx) {
        const int x0 = tx * kTile, y0 = ty * kTile;
        const int tileWidth = std::min(settings.width, x0 + kTile) - x0;
        const int count = tileWidth * (std::min(settings.height, y0 + kTile) - y0);
        pixels.clear();
        for (int p = 0; p < count; ++p)
          pixels.emplace_back(settings.seed, uint32_t(settings.firstSample), uint32_t(x0 + p % tileWidth),
                              uint32_t(y0 + p / tileWidth));
        sums.assign(size_t(count), Rgb(0.0));
        // The tile's (pixel, sample) pairs in order, kWaveSize at a time: a pixel's samples are neighbours
        // in a wave, so its packets' rays are as coherent as rays get, and each pixel's sum is taken in
        // sample order whatever the wave boundaries.
        int pixel = settings.spp > 0 ? 0 : count, sampleIndex = 0;
        while (pixel < count) {
          int lanes = 0;
          for (; lanes < kWaveSize && pixel < count; ++lanes) {
            lanePixel[lanes] = pixel;
            alive[lanes] = true;
            samplers[lanes] = CmjSampler(pattern, pixels[size_t(pixel)], uint32_t(sampleIndex));
            if (++sampleIndex == settings.spp) {
              sampleIndex = 0;
              ++pixel;
            }
          }
          CmjSampler::get2D(samplers, kLanes.data(), lanes, film);
          for (int i = 0; i < lanes; ++i) {
            const int p = lanePixel[i];
            rays[i] = cameraRays(Vec2(x0 + p % tileWidth, y0 + p / tileWidth) + film[i]);
          }
          std::fill(alive + lanes, alive + kWaveSize, false);
          tracer.traceWave(rays, samplers, alive, radiance, *workspace);
          for (int i = 0; i < lanes; ++i) {
            if (isFinite(radiance[i]))
              sums[size_t(lanePixel[i])] += radiance[i];
            else
              ++localDropped;
          }
        }
        for (int p = 0; p < count; ++p) {
          const Rgb mean = sums[size_t(p)] / double(std::max(1, settings.spp));
          float* px = image.at(x0 + p % tileWidth, y0 + p / tileWidth);
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
