// Where a sharp lobe's noise comes from at the first vertex (prints figures, asserts nothing): on the
// comparison sphere (bench/mitsuba/scene.py: radius 1, seen from (0, 1, 4), 35° vertical field of view) at
// the centres of a 64² grid of pixels, the variance of one sample of the direct light (luminance) with one
// light sample and M BSDF samples, combined by the power heuristic with counts as the path tracer does
// (direct_light.h, path_vertex.h), split into the light samples' part and the BSDF samples'. Unoccluded:
// the sphere is convex, so only its own horizon hides the map. Independent uniform draws (the renderer's
// are stratified, which lowers both parts).
// Usage: direct_light_split MATERIAL FIT (MAP.hdr | sky) [M ...]
//   e.g. direct_light_split aluminium microfacet:E2 ../shared/envmaps/studio_small_09_1k.hdr 1 8
#include "materials/core/frame.h"
#include "materials/models/brdf.h"
#include "materials/params/importer.h"
#include "materials/params/material_file.h"
#include "renderer/lights/environment.h"

#include <glm/geometric.hpp>

#include <cstdio>
#include <random>
#include <string>

using namespace glossy;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: direct_light_split MATERIAL FIT (MAP | sky) [M ...]\n");
    return 2;
  }
  const MaterialFile material =
      loadMaterialFile(std::string(GLOSSY_SOURCE_DIR) + "/materials/library/merl/" + argv[1] + ".toml");
  const Brdf brdf = makeBrdf(*material.find(FitId::parse(argv[2], "direct_light_split")));
  const std::string map = argv[3];
  const Environment environment = map == "sky" ? Environment::makeDefault() : Environment::load(map);
  std::vector<int> counts;
  for (int a = 4; a < argc; ++a) counts.push_back(std::max(1, std::atoi(argv[a])));
  if (counts.empty()) counts = {1, 8};

  constexpr int kSize = 64, kSamples = 512;
  const Vec3 eye(0, 1, 4), forward = glm::normalize(-eye);
  const Vec3 right = glm::normalize(glm::cross(forward, Vec3(0, 1, 0))), up = glm::cross(right, forward);
  const double halfHeight = std::tan(0.5 * 35.0 * kPi / 180.0);
  const auto power = [](double a, double b) { return a * a + b * b > 0.0 ? a * a / (a * a + b * b) : 0.0; };
  for (const int m : counts) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    double lightVariance = 0.0, bsdfVariance = 0.0, variance = 0.0, mean = 0.0;
    int pixels = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const Vec3 d = glm::normalize(forward + (2.0 * (x + 0.5) / kSize - 1.0) * halfHeight * right +
                                      (1.0 - 2.0 * (y + 0.5) / kSize) * halfHeight * up);
        const double b = glm::dot(eye, d), disc = b * b - (glm::dot(eye, eye) - 1.0);
        if (disc <= 0.0) continue;
        const Vec3 n = glm::normalize(eye + (-b - std::sqrt(disc)) * d);
        const Frame frame(n);
        const Vec3 wo = frame.toLocal(-d);
        if (wo.z < 0.05) continue;  // the silhouette, which the comparison's mask leaves out
        double sums[3][2] = {};  // light part, BSDF part, both: Σ x, Σ x²
        for (int s = 0; s < kSamples; ++s) {
          double light = 0.0, bsdf = 0.0;
          const Environment::Sample l = environment.sample(n, Vec2(uniform(random), uniform(random)));
          if (l.pdf > 0.0 && glm::dot(l.dir, n) > 0.0) {
            const Vec3 wi = frame.toLocal(l.dir);
            const BrdfValue v = evalPdf(brdf, wi, wo);
            light = luminance(v.f * l.radiance) * wi.z / l.pdf * power(l.pdf, m * v.pdf);
          }
          for (int j = 0; j < m; ++j) {
            const BrdfSample bs = sample(brdf, wo, uniform(random), Vec2(uniform(random), uniform(random)));
            if (!bs.valid()) continue;
            const Vec3 wi = frame.toWorld(bs.L);
            if (glm::dot(wi, n) <= 0.0) continue;
            double lightPdf = 0.0;
            const Rgb radiance = environment.radianceAndPdf(n, wi, lightPdf);
            bsdf += luminance(bs.weight * radiance) * power(m * bs.pdf, lightPdf) / m;
          }
          const double parts[3] = {light, bsdf, light + bsdf};
          for (int k = 0; k < 3; ++k) sums[k][0] += parts[k], sums[k][1] += parts[k] * parts[k];
        }
        const auto var = [&](int k) { return sums[k][1] / kSamples - std::pow(sums[k][0] / kSamples, 2); };
        lightVariance += var(0), bsdfVariance += var(1), variance += var(2), mean += sums[2][0] / kSamples;
        ++pixels;
      }
    std::printf("%s %s, %s, %d BSDF sample(s): %d points, mean %.4g; variance of a sample %.4g: light samples %.4g, "
                "BSDF samples %.4g (%.0f %%)\n",
                argv[1], argv[2], environment.description().c_str(), m, pixels, mean / pixels, variance / pixels,
                lightVariance / pixels, bsdfVariance / pixels, 100.0 * bsdfVariance / (lightVariance + bsdfVariance));
  }
}
