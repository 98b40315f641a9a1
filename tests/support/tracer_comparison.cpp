#include "tests/support/tracer_comparison.h"

#include "materials/merl/merl_table.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/lights/environment.h"
#include "renderer/scene/embree_scene.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace glossy::test {

BlockCheck compareBlocks(const std::vector<RgbImage>& wave, const std::vector<RgbImage>& reference, int blockSize) {
  const auto blockOf = [&](const std::vector<RgbImage>& images, int bx, int by, int c, double& mean, double& variance) {
    const double r = double(images.size()), pixels = double(blockSize) * blockSize;
    mean = variance = 0.0;
    for (int y = by; y < by + blockSize; ++y)
      for (int x = bx; x < bx + blockSize; ++x) {
        double sum = 0.0, squares = 0.0;
        for (const RgbImage& image : images) sum += image.at(x, y)[c];
        const double m = sum / r;
        for (const RgbImage& image : images) squares += (image.at(x, y)[c] - m) * (image.at(x, y)[c] - m);
        mean += m / pixels;
        variance += squares / (r - 1.0) / r / (pixels * pixels);
      }
  };
  struct Block {
    double mean[2], variance[2];  // of the block's mean: the wave's, the reference's
  };
  std::vector<Block> blocks;
  double brightest = 0.0;
  for (int by = 0; by + blockSize <= wave[0].height; by += blockSize)
    for (int bx = 0; bx + blockSize <= wave[0].width; bx += blockSize)
      for (int c = 0; c < 3; ++c) {
        Block b;
        blockOf(wave, bx, by, c, b.mean[0], b.variance[0]);
        blockOf(reference, bx, by, c, b.mean[1], b.variance[1]);
        brightest = std::max(brightest, b.mean[1]);
        blocks.push_back(b);
      }
  BlockCheck check;
  for (const Block& b : blocks) {
    const double se = std::sqrt(b.variance[0] + b.variance[1]);
    if (se > 0.0) check.worstZ = std::max(check.worstZ, std::abs(b.mean[0] - b.mean[1]) / se);
    else if (b.mean[0] != b.mean[1]) check.worstZ = INFINITY;  // both noiseless, and different
    if (!(b.mean[1] >= 0.1 * brightest) || !(brightest > 0.0)) continue;
    ++check.lit;
    check.worstDetectable = std::max(check.worstDetectable, 6.8 * se / b.mean[1]);
  }
  return check;
}

std::vector<TracerCase> tracerCases() {
  using Sky = TracerCase::Sky;
  const Brdf cookTorrance = CookTorrance{Rgb(0.1, 0.08, 0.05), Rgb(0.8, 0.6, 0.4), 0.12, 1.6};
  const Brdf sharp = CookTorrance{Rgb(0.02), Rgb(0.2), 0.0125, 1.7};
  return {
      {"environment only", cookTorrance, false, Sky::Default, 8, 100, 4, true, 1664},
      {"environment and emitters", cookTorrance, true, Sky::Default, 8, 100, 4, true, 1472},
      {"emitters only", Lambertian{Rgb(0.7)}, true, Sky::None, 8, 100, 4, true, 4672},
      {"measured table", Measured(tabulateMerl(cookTorrance)), true, Sky::Default, 4, 100, 4, true, 2112},
      {"Russian roulette", cookTorrance, true, Sky::Default, 8, 2, 4, true, 1536},
      {"max depth 1", cookTorrance, true, Sky::Default, 1, 100, 4, true, 128},
      {"one light sample", cookTorrance, true, Sky::Default, 8, 100, 1, true, 1536},
      {"three light samples everywhere", cookTorrance, true, Sky::Default, 8, 100, 3, false, 1408},
      {"a sharp sphere, its samples traced", sharp, true, Sky::Default, 8, 100, 4, true, 1984},
      {"a sharp sphere, its samples resampled", sharp, false, Sky::Default, 8, 100, 4, true, 5504},
      {"a sharp sphere under small bright panels", sharp, false, Sky::Panels, 8, 100, 4, true, 7168},
  };
}

BlockCheck compareTracers(const TracerCase& c, int waveSpp, int blockSize) {
  const SphereOnFloor stage(c.brdf, c.lamp);
  const TempDir dir;
  std::optional<Environment> sky;
  if (c.sky == TracerCase::Sky::Default) sky.emplace(Environment::makeDefault());
  if (c.sky == TracerCase::Sky::Panels) {
    writePanelsMap(dir / "panels.exr", 48, 25);
    sky.emplace(Environment::load(dir / "panels.exr"));
  }
  const EmbreeScene bvh(stage.description);
  const RenderScene scene{&stage.description, &bvh, stage.brdfs, Lambertian{Rgb(0.5)}, sky ? &*sky : nullptr};
  const Camera camera = perspective({0, 1.5, 5}, {0, 0, 0}, 0.7);
  std::vector<RgbImage> wave, reference;
  for (uint32_t r = 0; r < 4; ++r) {
    RenderSettings s;
    s.width = 40;
    s.height = 32;
    s.threads = 2;
    s.progress = false;
    s.maxDepth = c.maxDepth;
    s.rouletteDepth = c.rouletteDepth;
    s.lightSamples = c.lightSamples;
    s.lightSamplesPerBrdf = c.perBrdf;
    s.spp = waveSpp;
    s.seed = 10 + r;
    RenderStats stats;
    wave.push_back(render(scene, camera, s, stats));
    s.reference = true;
    s.spp = 4 * waveSpp;
    s.seed = 20 + r;
    reference.push_back(render(scene, camera, s, stats));
  }
  const BlockCheck check = compareBlocks(wave, reference, blockSize);
  std::printf("%-42s worst z %.2f over %zu block channels; bias caught with 99 %% probability: %.2f %% (%d lit)\n", c.name,
              check.worstZ, size_t(40 / blockSize) * size_t(32 / blockSize) * 3, 100.0 * check.worstDetectable, check.lit);
  return check;
}

}  // namespace glossy::test
