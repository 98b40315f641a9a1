// What lobe sampling is worth, measured (prints a table, asserts nothing): relative RMSE over the object's
// pixels of a sphere render against a converged reference, at equal spp, with each model sampling its own
// lobe vs the cosine lobe; and the convergence of the most extreme published fits.
#include "materials/params/importer.h"
#include "materials/params/material_file.h"
#include "bench/sphere_variance.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace glossy;
using glossy::bench::Setup;

int main(int argc, char** argv) {
  CLI::App app{"sampling_variance: relative RMSE of lobe vs cosine BRDF sampling at equal spp"};
  int size = 64, spp = 64, refSpp = 4096;
  std::string shared = std::string(GLOSSY_SOURCE_DIR) + "/../shared";
  app.add_option("--size", size)->capture_default_str();
  app.add_option("--spp", spp, "Samples per pixel of the compared renders")->capture_default_str();
  app.add_option("--reference-spp", refSpp, "Samples per pixel of the lobe-sampled reference")->capture_default_str();
  app.add_option("--shared", shared, "The shared/ folder (for the extreme published fits)")->capture_default_str();
  bool extremesOnly = false;
  app.add_flag("--extremes-only", extremesOnly, "Only the convergence of the most extreme published fits");
  CLI11_PARSE(app, argc, argv);

  const Setup setup(size);
  if (!extremesOnly) {
    std::printf("Sphere (scenes/sphere.gltf), default sky, %dx%d, max depth 3; relative RMSE over the sphere's pixels against "
                "a lobe-sampled reference at %d spp; both at %d spp.\n\n",
                size, size, refSpp, spp);
    std::printf("| material | fit | lobe | cosine | cosine/lobe | spp factor |\n|---|---|---|---|---|---|\n");
    std::vector<double> factors;
    for (const char* name : {"alum-bronze", "blue-acrylic", "blue-rubber", "chrome", "gold-metallic-paint2", "gold-paint"}) {
      const MaterialFile m = loadMaterialFile(std::filesystem::path(GLOSSY_SOURCE_DIR) / "materials/library/merl" / (std::string(name) + ".toml"));
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
  }

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
