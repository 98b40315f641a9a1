// The image: tiles of pixels, each pixel's samples in order, traced by the wave (or the reference path
// tracer), averaged per pixel.
#include "renderer/integrator/path_tracer.h"

#include "renderer/camera/camera_rays.h"
#include "renderer/integrator/path_vertex.h"
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

RgbImage render(const RenderScene& scene, const Camera& camera, const RenderSettings& settings, RenderStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  RgbImage image(settings.width, settings.height);
  const LightSet lights(LightSources{*scene.description, scene.environment, scene.bvh->boundsRadius()});
  const PathContext context{scene, settings, lights};
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
    auto wave = std::make_unique<WaveTracer>(context);
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
          auto pixelCorner = [&](int i) { return Vec2(x0 + lanePixel[i] % tileWidth, y0 + lanePixel[i] / tileWidth); };
          if (settings.reference) {
            for (int i = 0; i < lanes; ++i)
              radiance[i] = tracePath(context, cameraRays(pixelCorner(i) + samplers[i].get2D()), samplers[i]);
          } else {
            CmjSampler::get2D(samplers, kLanes.data(), lanes, film);
            for (int i = 0; i < lanes; ++i) rays[i] = cameraRays(pixelCorner(i) + film[i]);
            std::fill(alive + lanes, alive + kWaveSize, false);
            wave->trace(rays, samplers, alive, radiance);
          }
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
