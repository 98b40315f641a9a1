// The image (or a sheet's panels): tiles of pixels, each pixel's samples in order, traced by the wave (or
// the reference path tracer), averaged per pixel.
#include "renderer/integrator/path_tracer.h"

#include "renderer/camera/camera_rays.h"
#include "renderer/integrator/shared_draws.h"
#include "renderer/util/progress.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

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
// 0, 1, …, kWaveSize − 1: every lane of a wave, for the batch draws.
constexpr std::array<int, kWaveSize> kLanes = [] {
  std::array<int, kWaveSize> lanes{};
  for (int i = 0; i < kWaveSize; ++i) lanes[i] = i;
  return lanes;
}();

bool isFinite(const Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

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
  const size_t panelCount = panels.size();
  std::vector<RgbImage> images(panelCount, RgbImage(settings.width, settings.height));
  const RenderScene& first = panels.front();
  const LightSet lights(LightSources{*first.description, first.environment, first.bvh->boundsRadius()});
  std::vector<PathContext> contexts;
  for (const RenderScene& panel : panels) contexts.push_back({panel, settings, lights});
  // One panel needs no stops: its paths run to their end in the first pass.
  const bool stop = panelCount > 1;
  std::atomic<uint64_t> dropped{0}, objectPaths{0};
  const int tilesX = (settings.width + kTile - 1) / kTile, tilesY = (settings.height + kTile - 1) / kTile;
  Progress progress("render", size_t(tilesX) * size_t(tilesY));
  if (!settings.progress) progress.finish();

  const CameraRays cameraRays(camera, settings.width, settings.height);
  const CmjPattern pattern(uint32_t(std::max(1, settings.spp)), uint32_t(std::clamp(settings.lightSamples, 1, kMaxLightSamples)));
  auto renderTileRange = [&](const tbb::blocked_range2d<int>& tiles) {
    uint64_t localDropped = 0, localObjectPaths = 0;
    CmjSampler samplers[kWaveSize];
    Ray rays[kWaveSize];
    bool alive[kWaveSize];
    Rgb radiance[kWaveSize], resumed[kWaveSize];
    int lanePixel[kWaveSize];  // which of the tile's pixels each lane samples
    Vec2 film[kWaveSize];
    SharedDraws shared(settings.maxDepth);
    std::vector<std::unique_ptr<WaveTracer>> waves;
    for (const PathContext& context : contexts)
      waves.push_back(std::make_unique<WaveTracer>(context, stop ? &shared : nullptr));
    auto stops = std::make_unique<ObjectVertex[]>(kWaveSize);
    // Paths stopped at the object, by depth, waiting to continue in every panel a wave at a time (a wave
    // advances its lanes one depth at a time).
    std::vector<std::vector<ObjectVertex>> waiting(size_t(std::max(1, settings.maxDepth)));
    std::vector<std::vector<int>> waitingPixel(waiting.size());
    std::vector<CmjPixel> pixels;
    std::vector<Rgb> sums;  // [panel][pixel]
    pixels.reserve(size_t(kTile) * kTile);

    auto add = [&](size_t panel, int pixel, const Rgb& r, size_t count) {
      if (isFinite(r))
        sums[panel * count + size_t(pixel)] += r;
      else
        ++localDropped;
    };
    // Each panel continues the waiting paths of one depth.
    auto resume = [&](size_t depth, size_t count) {
      std::vector<ObjectVertex>& vertices = waiting[depth];
      const int n = int(vertices.size());
      for (size_t p = 0; p < panelCount; ++p) {
        if (settings.reference)
          for (int i = 0; i < n; ++i) resumed[i] = continueFromObject(contexts[p], vertices[size_t(i)]);
        else
          waves[p]->resume(vertices.data(), n, resumed);
        for (int i = 0; i < n; ++i) add(p, waitingPixel[depth][size_t(i)], resumed[i], count);
      }
      vertices.clear();
      waitingPixel[depth].clear();
    };

    for (int ty = tiles.rows().begin(); ty < tiles.rows().end(); ++ty)
      for (int tx = tiles.cols().begin(); tx < tiles.cols().end(); ++tx) {
        if (settings.control && settings.control->cancelRequested()) return;
        const int x0 = tx * kTile, y0 = ty * kTile;
        const int tileWidth = std::min(settings.width, x0 + kTile) - x0;
        const int count = tileWidth * (std::min(settings.height, y0 + kTile) - y0);
        pixels.clear();
        for (int p = 0; p < count; ++p)
          pixels.emplace_back(settings.seed, uint32_t(settings.firstSample), uint32_t(x0 + p % tileWidth),
                              uint32_t(y0 + p / tileWidth));
        sums.assign(panelCount * size_t(count), Rgb(0.0));
        // The tile's (pixel, sample) pairs in order, kWaveSize at a time: a pixel's samples are neighbours
        // in a wave, so its packets' rays are as coherent as rays get, and each pixel's sum is taken in
        // sample order whatever the wave boundaries (the paths that stopped at the object join their sums
        // when their depth has a wave's worth, which differs from sample order only in rounding).
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
          auto pixelCorner = [&](int i) { return Vec2(x0 + lanePixel[i] % tileWidth, y0 + lanePixel[i] / tileWidth); };
          if (settings.reference) {
            for (int i = 0; i < lanes; ++i) {
              const Ray ray = cameraRays(pixelCorner(i) + samplers[i].get2D());
              if (stop)
                traceToObject(contexts[0], ray, samplers[i], radiance[i], stops[size_t(i)]);
              else
                radiance[i] = Li(contexts[0], ray, samplers[i]);
            }
          } else {
            CmjSampler::get2D(samplers, kLanes.data(), lanes, film);
            for (int i = 0; i < lanes; ++i) rays[i] = cameraRays(pixelCorner(i) + film[i]);
            std::fill(alive + lanes, alive + kWaveSize, false);
            waves[0]->trace(rays, samplers, alive, radiance, stop ? stops.get() : nullptr);
          }
          for (int i = 0; i < lanes; ++i) {
            const ObjectVertex& v = stops[size_t(i)];
            if (!stop || v.depth == 0) {
              // Never met the object: the same path in every panel.
              for (size_t p = 0; p < panelCount; ++p) add(p, lanePixel[i], radiance[i], size_t(count));
              continue;
            }
            ++localObjectPaths;
            waiting[size_t(v.depth)].push_back(v);
            waitingPixel[size_t(v.depth)].push_back(lanePixel[i]);
            if (waiting[size_t(v.depth)].size() == size_t(kWaveSize)) resume(size_t(v.depth), size_t(count));
          }
        }
        // The samplers of waiting paths point at this tile's pixels: finish them before the next tile.
        for (size_t depth = 0; depth < waiting.size(); ++depth)
          if (!waiting[depth].empty()) resume(depth, size_t(count));
        for (size_t p = 0; p < panelCount; ++p)
          for (int i = 0; i < count; ++i) {
            const Rgb mean = sums[p * size_t(count) + size_t(i)] / double(std::max(1, settings.spp));
            float* px = images[p].at(x0 + i % tileWidth, y0 + i / tileWidth);
            for (int c = 0; c < 3; ++c) px[c] = float(std::min(mean[c], double(std::numeric_limits<float>::max())));
          }
        progress.advance();
        if (settings.control) settings.control->done.fetch_add(1, std::memory_order_relaxed);
      }
    dropped += localDropped;
    objectPaths += localObjectPaths;
  };

  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  arena.execute([&] { tbb::parallel_for(tbb::blocked_range2d<int>(0, tilesY, 1, 0, tilesX, 1), renderTileRange); });
  progress.finish();
  stats.droppedSamples = dropped.load();
  stats.objectPaths = objectPaths.load();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return images;
}

}  // namespace glossy
