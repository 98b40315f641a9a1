// What lobe sampling is worth, measured (prints a table, asserts nothing): relative RMSE over the object's
// pixels of a sphere render against a converged reference, at equal spp, with each model sampling its own
// lobe vs the cosine lobe; and the convergence of the most extreme published fits.
#include "materials/params/importer.h"
#include "materials/params/material_file.h"
#include "renderer/camera/camera_rays.h"
#include "renderer/integrator/path_tracer.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace glossy;

namespace {

struct Setup {
  SceneDescription description;
  std::unique_ptr<EmbreeScene> bvh;
  std::unique_ptr<AreaLights> lights;
  Environment environment = Environment::makeDefault();
  std::vector<char> mask;  // pixels whose centre sees the object

  Setup(int size) {
    description = loadGltf(std::filesystem::path(GLOSSY_SOURCE_DIR) / "scenes/sphere.gltf");
    bvh = std::make_unique<EmbreeScene>(description);
    lights = std::make_unique<AreaLights>(description);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        Hit hit;
        mask.push_back(bvh->intersect(cameraRay(description.cameras.front(), size, size, Vec2(x + 0.5, y + 0.5)), hit));
      }
  }

  RgbImage render(const Brdf& brdf, int size, int spp, bool cosine, uint32_t seed) const {
    std::vector<Brdf> brdfs(description.materials.size(), brdf);
    const RenderScene scene{&description, bvh.get(), brdfs, brdf, &environment, lights.get()};
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sampling_variance: relative RMSE of lobe vs cosine BRDF sampling at equal spp"};
  int size = 64, spp = 64, refSpp = 4096;
  std::string shared = std::string(GLOSSY_SOURCE_DIR) + "/../shared";
  app.add_option("--size", size)->capture_default_str();
  app.add_option("--spp", spp, "Samples per pixel of the compared renders")->capture_default_str();
  app.add_option("--reference-spp", refSpp, "Samples per pixel of the lobe-sampled reference")->capture_default_str();
  app.add_option("--shared", shared, "The shared/ folder (for the extreme published fits)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const Setup setup(size);
  std::printf("Sphere (scenes/sphere.gltf), default sky, %dx%d, max depth 3; relative RMSE over the sphere's pixels against "
              "a lobe-sampled reference at %d spp; both at %d spp.\n\n",
              size, size, refSpp, spp);
  std::printf("| material | fit | lobe | cosine | cosine/lobe | spp factor |\n|---|---|---|---|---|---|\n");
  std::vector<double> factors;
  for (const char* name : {"alum-bronze", "blue-acrylic", "blue-rubber", "chrome", "gold-metallic-paint2", "gold-paint"}) {
    const MaterialFile m = loadMaterialFile(std::filesystem::path(GLOSSY_SOURCE_DIR) / "materials" / (std::string(name) + ".toml"));
    for (const Fit& fit : m.fits) {
      const Brdf brdf = makeBrdf(fit);
      const RgbImage ref = setup.render(brdf, size, refSpp, false, 1000);
      const double lobe = setup.relativeRmse(setup.render(brdf, size, spp, false, 1), ref);
      const double cosine = setup.relativeRmse(setup.render(brdf, size, spp, true, 1), ref);
      // RMSE falls as 1/sqrt(spp): the cosine sampler needs (cosine/lobe)^2 times the samples.
      const double factor = (cosine / lobe) * (cosine / lobe);
      factors.push_back(factor);
      std::printf("| %s | %s | %.4f | %.4f | %.1f | %.0f |\n", name, fit.id.str().c_str(), lobe, cosine, cosine / lobe, factor);
      std::fflush(stdout);
    }
  }
  std::sort(factors.begin(), factors.end());
  std::printf("\nMedian spp factor (samples cosine sampling needs for lobe sampling's error): %.0f; range %.1f to %.0f\n",
              factors[factors.size() / 2], factors.front(), factors.back());

  // The most extreme published fits: AS with the largest n, Microfacet with the largest B.
  auto extreme = [&](const char* file, const char* key) {
    std::ifstream in(std::filesystem::path(shared) / "fits" / file);
    std::stringstream text;
    text << in.rdbuf();
    const auto all = importFitLines(text.str(), file);
    const MaterialFile* best = &all.front();
    for (const MaterialFile& m : all)
      if (m.fits[0].params.scalar(key) > best->fits[0].params.scalar(key)) best = &m;
    return std::pair{best->name, best->fits[0]};
  };
  std::printf("\nMost extreme published fits (reference %d spp):\n\n| material | fit | parameter | spp | lobe | cosine |\n|---|---|---|---|---|---|\n",
              4 * refSpp);
  for (const auto& [file, key] : {std::pair{"low_ashikhminshirley_E1.fit", "n"}, std::pair{"low_lowmicrofacet_E2.fit", "b"}}) {
    if (!std::filesystem::exists(std::filesystem::path(shared) / "fits" / file)) continue;
    const auto [name, fit] = extreme(file, key);
    const Brdf brdf = makeBrdf(fit);
    const RgbImage ref = setup.render(brdf, size, 4 * refSpp, false, 1000);
    for (int n : {64, 1024})
      std::printf("| %s | %s | %s = %.4g | %d | %.4f | %.4f |\n", name.c_str(), fit.id.str().c_str(), key, fit.params.scalar(key), n,
                  setup.relativeRmse(setup.render(brdf, size, n, false, 1), ref),
                  setup.relativeRmse(setup.render(brdf, size, n, true, 1), ref));
  }
  return 0;
}
