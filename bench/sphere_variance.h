// The variance benches' common ground: the sphere scene (scenes/sphere.gltf) under the built-in sky (or a
// given environment), max depth 3, rendered with one BRDF on every mesh, and relative RMSE over the
// sphere's pixels.
#pragma once

#include "renderer/camera/camera_rays.h"
#include "renderer/integrator/path_tracer.h"

#include <cmath>
#include <memory>
#include <vector>

namespace glossy::bench {

struct Setup {
  SceneDescription description;
  std::unique_ptr<EmbreeScene> bvh;
  Environment environment = Environment::makeDefault();
  std::vector<char> mask;  // pixels whose centre sees the object

  explicit Setup(int size, Environment env = Environment::makeDefault()) : environment(std::move(env)) {
    description = loadGltf(std::filesystem::path(GLOSSY_SOURCE_DIR) / "scenes/sphere.gltf");
    bvh = std::make_unique<EmbreeScene>(description);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        Hit hit;
        mask.push_back(bvh->intersect(cameraRay(description.cameras.front(), size, size, Vec2(x + 0.5, y + 0.5)), hit));
      }
  }

  RgbImage render(const Brdf& brdf, int size, int spp, bool cosine, uint32_t seed) const {
    std::vector<Brdf> brdfs(description.materials.size(), brdf);
    const RenderScene scene{&description, bvh.get(), brdfs, brdf, &environment};
    RenderSettings s;
    s.width = s.height = size;
    s.spp = spp;
    s.maxDepth = 3;
    s.seed = seed;
    s.progress = false;
    s.cosineBrdfSampling = cosine;
    RenderStats stats;
    return glossy::render(scene, description.cameras.front(), s, stats);
  }

  double relativeRmse(const RgbImage& img, const RgbImage& ref) const {
    double err = 0.0, norm = 0.0;
    for (size_t i = 0; i < mask.size(); ++i) {
      if (!mask[i]) continue;
      for (int c = 0; c < 3; ++c) {
        const double d = img.pixels[3 * i + c] - ref.pixels[3 * i + c];
        err += d * d;
        norm += double(ref.pixels[3 * i + c]) * ref.pixels[3 * i + c];
      }
    }
    return std::sqrt(err / norm);
  }
};

}  // namespace glossy::bench
