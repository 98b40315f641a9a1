// The image (or a sheet's panels): tiles of pixels, each pixel's samples in order, their camera rays a wave
// at a time traced by the panel tracer (panel_split.h), averaged per pixel; or each path by the reference
// path tracer (reference_path.h).
#include "renderer/integrator/path_tracer.h"

#include "renderer/camera/camera_rays.h"
#include "renderer/integrator/light_count.h"
#include "renderer/integrator/panel_split.h"
#include "renderer/integrator/reference_path.h"
#include "renderer/util/progress.h"

#include <tbb/blocked_range2d.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace glossy {

namespace {

constexpr int kTile = 16;

// A pixel's mean of spp samples' sum, as float (clamped to the largest float).
void writeMean(const Rgb& sum, int spp, float* px) {
  const Rgb mean = sum / double(std::max(1, spp));
  for (int c = 0; c < 3; ++c) px[c] = float(std::min(mean[c], double(std::numeric_limits<float>::max())));
}

// A thread's renderer of tiles, its lanes' state reused from tile to tile.
class TileRenderer {
 public:
  TileRenderer(std::span<const PathContext> panels, const CameraRays& cameraRays, const CmjPattern& pattern,
               std::vector<RgbImage>& images)
      : settings_(panels[0].settings), cameraRays_(cameraRays), pattern_(pattern), images_(images),
        tracer_(panels) {}

  void render(int tx, int ty) {
    start(tx, ty);
    for (int lanes; (lanes = nextWave()) > 0;) tracer_.trace(rays_, samplers_, lanePixel_, lanes, sums_);
    tracer_.resumeAll(sums_);
    write();
  }
  void addStats(RenderStats& stats) const {
    stats.droppedSamples += sums_.dropped;
    stats.objectPaths += tracer_.objectPaths;
  }

 private:
  void start(int tx, int ty) {
    x0_ = tx * kTile;
    y0_ = ty * kTile;
    width_ = std::min(settings_.width, x0_ + kTile) - x0_;
    count_ = width_ * (std::min(settings_.height, y0_ + kTile) - y0_);
    pixels_.clear();
    for (int p = 0; p < count_; ++p)
      pixels_.emplace_back(settings_.seed, uint32_t(settings_.firstSample), uint32_t(x0_ + p % width_), uint32_t(y0_ + p / width_));
    sums_.pixels = size_t(count_);
    sums_.sum.assign(images_.size() * size_t(count_), Rgb(0.0));
    next_ = 0;
  }

  // The camera rays of the tile's next (pixel, sample) pairs in order, up to a wave of them: a pixel's
  // samples are neighbours in a wave, so its packets' rays are as coherent as rays get, and each pixel's
  // sum is taken in sample order whatever the wave boundaries (the paths parked at the object join their
  // sums later, which differs from sample order only in rounding).
  int nextWave() {
    const int64_t spp = settings_.spp;
    int lanes = 0;
    while (lanes < kWaveSize && next_ < count_ * spp) {
      const int p = int(next_ / spp);
      if (settings_.pixels && !(*settings_.pixels)[size_t(y0_ + p / width_) * size_t(settings_.width) + size_t(x0_ + p % width_)]) {
        next_ = int64_t(p + 1) * spp;  // not traced: its samples are skipped
        continue;
      }
      lanePixel_[lanes] = p;
      samplers_[lanes++] = CmjSampler(pattern_, pixels_[size_t(p)], uint32_t(next_++ % spp));
    }
    CmjSampler::get2D(samplers_, Lanes::first(lanes).lane, lanes, film_);
    for (int i = 0; i < lanes; ++i)
      rays_[i] = cameraRays_(Vec2(x0_ + lanePixel_[i] % width_, y0_ + lanePixel_[i] / width_) + film_[i]);
    return lanes;
  }

  void write() {
    for (size_t p = 0; p < images_.size(); ++p)
      for (int i = 0; i < count_; ++i)
        writeMean(sums_.sum[p * size_t(count_) + size_t(i)], settings_.spp, images_[p].at(x0_ + i % width_, y0_ + i / width_));
  }

  const RenderSettings& settings_;
  const CameraRays& cameraRays_;
  const CmjPattern& pattern_;
  std::vector<RgbImage>& images_;
  PanelTracer tracer_;
  int x0_ = 0, y0_ = 0, width_ = 0, count_ = 0;  // the tile, count_ its pixels
  int64_t next_ = 0;  // the next sample to trace: pixel next_ / spp, its sample next_ % spp
  std::vector<CmjPixel> pixels_;
  PanelSums sums_;
  CmjSampler samplers_[kWaveSize];
  int lanePixel_[kWaveSize];  // which of the tile's pixels each lane samples
  Vec2 film_[kWaveSize];
  Ray rays_[kWaveSize];
};

// A thread's renderer of tiles by the reference path tracer: each panel's paths one at a time, each pixel's
// random numbers its own (the same in every panel).
class ReferenceTiles {
 public:
  ReferenceTiles(std::span<const PathContext> panels, const CameraRays& cameraRays, std::vector<RgbImage>& images)
      : panels_(panels), cameraRays_(cameraRays), images_(images) {}

  void render(int tx, int ty) {
    const RenderSettings& s = panels_[0].settings;
    for (int y = ty * kTile; y < std::min(s.height, (ty + 1) * kTile); ++y)
      for (int x = tx * kTile; x < std::min(s.width, (tx + 1) * kTile); ++x) {
        if (s.pixels && !(*s.pixels)[size_t(y) * size_t(s.width) + size_t(x)]) continue;
        for (size_t p = 0; p < panels_.size(); ++p) {
          ReferenceRandom random(s.seed, uint32_t(s.firstSample), uint32_t(x), uint32_t(y));
          Rgb sum(0.0);
          for (int k = 0; k < s.spp; ++k) {
            const Rgb r = referenceRadiance(panels_[p], cameraRays_(Vec2(x, y) + random.next2D()), random);
            if (std::isfinite(r.r) && std::isfinite(r.g) && std::isfinite(r.b)) sum += r;
            else ++dropped_;
          }
          writeMean(sum, s.spp, images_[p].at(x, y));
        }
      }
  }
  void addStats(RenderStats& stats) const { stats.droppedSamples += dropped_; }

 private:
  std::span<const PathContext> panels_;
  const CameraRays& cameraRays_;
  std::vector<RgbImage>& images_;
  uint64_t dropped_ = 0;
};

// Every tile of the image by a Tiles renderer per thread (made by make), with progress, the settings'
// threads and cancellation; their statistics summed into stats.
template <class Tiles, class Make>
void renderEachTile(const RenderSettings& settings, Make&& make, RenderStats& stats) {
  tbb::enumerable_thread_specific<std::unique_ptr<Tiles>> renderers(make);
  const int tilesX = (settings.width + kTile - 1) / kTile, tilesY = (settings.height + kTile - 1) / kTile;
  Progress progress("render", size_t(tilesX) * size_t(tilesY));
  if (!settings.progress) progress.finish();
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1), [&](const tbb::blocked_range2d<int>& tiles) {
      Tiles& renderer = *renderers.local();
      for (int ty = tiles.rows().begin(); ty < tiles.rows().end(); ++ty)
        for (int tx = tiles.cols().begin(); tx < tiles.cols().end(); ++tx) {
          if (settings.control && settings.control->cancelRequested()) return;
          renderer.render(tx, ty);
          progress.advance();
          if (settings.control) settings.control->done.fetch_add(1, std::memory_order_relaxed);
        }
    });
  });
  progress.finish();
  for (const std::unique_ptr<Tiles>& renderer : renderers) renderer->addStats(stats);
}

// The panel's own light and BSDF samples per material at a first vertex (light_count.h).
LightCounts lightCounts(const RenderScene& scene, const RenderSettings& settings, const LightSet& lights) {
  const int most = std::clamp(settings.lightSamples, 1, kMaxLightSamples);
  // Fixed counts give settings.bsdfSamples to a sheet's object (its materials), or everywhere outside sheets.
  std::vector<bool> object(scene.brdfs.size() + 1, scene.objectMeshes.empty());
  for (size_t mesh = 0; mesh < scene.objectMeshes.size(); ++mesh)
    if (scene.objectMeshes[mesh]) object[size_t(scene.description->meshes[mesh].material + 1)] = true;
  LightCounts counts;
  for (size_t m = 0; m <= scene.brdfs.size(); ++m) {
    const Brdf& brdf = m == 0 ? scene.defaultBrdf : scene.brdfs[m - 1];
    counts.taken.push_back(settings.lightSamplesPerBrdf ? lightSamplesFor(brdf, most) : most);
    counts.bsdf.push_back(settings.lightSamplesPerBrdf ? bsdfSamplesFor(brdf, !lights.onSurfaces())
                          : object[m]                  ? std::clamp(settings.bsdfSamples, 1, kMaxBsdfSamples)
                                                       : 1);
  }
  return counts;
}

// The counts every panel of a sheet takes: per material, the most any panel's own counts give, so that the
// panels share every draw and shadow ray up to where their BRDFs part (any count is unbiased: the MIS
// weights are the vertex's counts). A sheet's fixed counts (lightSamplesPerBrdf off) are the same in
// every panel anyway.
LightCounts panelCounts(std::span<const RenderScene> panels, const RenderSettings& settings, const LightSet& lights) {
  LightCounts counts = lightCounts(panels.front(), settings, lights);
  for (const RenderScene& panel : panels.subspan(1)) {
    const LightCounts own = lightCounts(panel, settings, lights);
    for (size_t m = 0; m < counts.taken.size(); ++m) {
      counts.taken[m] = std::max(counts.taken[m], own.taken[m]);
      counts.bsdf[m] = std::max(counts.bsdf[m], own.bsdf[m]);
    }
  }
  return counts;
}

}  // namespace

uint64_t renderTiles(int width, int height) {
  return uint64_t((width + kTile - 1) / kTile) * uint64_t((height + kTile - 1) / kTile);
}

RgbImage render(const RenderScene& scene, const Camera& camera, const RenderSettings& settings, RenderStats& stats) {
  return std::move(renderPanels({&scene, 1}, camera, settings, stats).front());
}

std::vector<RgbImage> renderPanels(std::span<const RenderScene> panels, const Camera& camera, const RenderSettings& settings,
                                   RenderStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  if (settings.pixels && settings.pixels->size() != size_t(settings.width) * size_t(settings.height))
    throw std::invalid_argument("renderPanels: the pixel mask is not width × height");
  std::vector<RgbImage> images(panels.size(), RgbImage(settings.width, settings.height));
  const LightSet lights(LightSources{*panels.front().description, panels.front().environment, panels.front().bvh->boundsRadius()});
  const LightCounts counts = panelCounts(panels, settings, lights);
  std::vector<PathContext> contexts;
  for (const RenderScene& panel : panels) contexts.push_back({panel, settings, lights, counts});
  const CameraRays cameraRays(camera, settings.width, settings.height);
  stats = RenderStats{};
  if (settings.reference) {
    renderEachTile<ReferenceTiles>(settings, [&] { return std::make_unique<ReferenceTiles>(contexts, cameraRays, images); }, stats);
  } else {
    // Split patterns for every count of light or BSDF samples the first vertices take.
    int splits = 1;
    for (size_t m = 0; m < counts.taken.size(); ++m) splits = std::max({splits, counts.taken[m], counts.bsdf[m]});
    const CmjPattern pattern(uint32_t(std::max(1, settings.spp)), uint32_t(splits));
    renderEachTile<TileRenderer>(settings, [&] { return std::make_unique<TileRenderer>(contexts, cameraRays, pattern, images); }, stats);
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return images;
}

}  // namespace glossy
