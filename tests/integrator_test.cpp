// The path tracer's two forms and its lights: the wave's image has the reference path tracer's expectation; an
// environment (constant, or a map of bright panels) and emitters together match their irradiance (both
// sides of MIS, the emitter hiding part of the sky); the light chooser draws by power; a scene renders
// alike at 1e-3 and 1e3 of its size; a light 1e-5 above a surface lights it.
#include "renderer/integrator/light_count.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/lights/light_set.h"
#include "tests/support/image_regression.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/tracer_comparison.h"
#include "tests/support/test_support.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <functional>
#include <vector>

namespace glossy::test {

namespace {

RgbImage renderScene(const SceneDescription& description, const std::vector<Brdf>& brdfs, const Environment* environment,
                     const Camera& camera, const RenderSettings& settings) {
  const EmbreeScene bvh(description);
  const RenderScene scene{&description, &bvh, brdfs, Lambertian{Rgb(0.5)}, environment};
  RenderStats stats;
  return render(scene, camera, settings, stats);
}

RenderSettings quiet(int width, int height, int spp, uint32_t seed = 1) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.spp = spp;
  s.seed = seed;
  s.threads = 2;
  s.progress = false;
  return s;
}

// A Lambertian floor (albedo 0.5) and a square lamp 1 above it, facing down, seen from above by a 40 × 40
// orthographic camera over x, z in [−2, 2].
struct LampOverFloor {
  static constexpr int kSize = 40;
  static constexpr double kHalf = 0.2;  // the lamp's half width
  SceneDescription description;
  std::vector<Brdf> brdfs = {Lambertian{Rgb(0.5)}, Lambertian{Rgb(0.0)}};
  Camera camera = orthographicDown(2.0, {0, 5, 0}, {0, 0, 0}, {0, 0, -1});
  glm::dvec3 lamp[4] = {{-kHalf, 1, -kHalf}, {kHalf, 1, -kHalf}, {kHalf, 1, kHalf}, {-kHalf, 1, kHalf}};

  explicit LampOverFloor(Rgb emission) {
    description.materials = {material("floor"), material("lamp", Rgb(0.0), emission)};
    description.meshes.push_back(quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0));
    description.meshes.push_back(quad({-float(kHalf), 1, -float(kHalf)}, {2 * float(kHalf), 0, 0}, {0, 0, 2 * float(kHalf)}, 1));
  }
  // The floor point seen at film position (px, py), in pixels.
  static glm::dvec3 floorPoint(double px, double py) {
    return {(2.0 * px / kSize - 1.0) * 2.0, 0.0, -(1.0 - 2.0 * py / kSize) * 2.0};
  }
  // Every other pixel, less those whose floor the lamp's back hides from the camera.
  static bool checked(int x, int y) {
    const glm::dvec3 p = floorPoint(x + 0.5, y + 0.5);
    return x % 2 == 1 && y % 2 == 1 && !(std::abs(p.x) < kHalf + 0.3 && std::abs(p.z) < kHalf + 0.3);
  }
};

// Two independent renders a, b against the expected value want(x, y, channel) of the checked pixels: the
// summed error against the summed variance (a uniform bias), and the squared errors against the variances
// (a bias in some pixels), with the variance of each pixel's mean estimated from the halves, ((a − b)/2)².
void expectUnbiased(const RgbImage& a, const RgbImage& b, const std::function<bool(int, int)>& checked,
                    const std::function<double(int, int, int)>& want) {
  for (int c = 0; c < 3; ++c) {
    double error = 0.0, squared = 0.0, variance = 0.0;
    int count = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        if (!checked(x, y)) continue;
        const double expected = want(x, y, c);
        const double mean = 0.5 * (a.at(x, y)[c] + b.at(x, y)[c]), half = 0.5 * (a.at(x, y)[c] - b.at(x, y)[c]);
        error += mean - expected;
        squared += (mean - expected) * (mean - expected);
        variance += half * half;
        ++count;
      }
    ASSERT_GT(count, 300);
    EXPECT_LT(std::abs(error) / std::sqrt(variance), 4.0) << "channel " << c << ": mean error " << error / count;
    // E[squared] = E[variance]; their ratio over ~370 pixels is 1 ± 0.1 (both are sums of χ²-like terms).
    EXPECT_LT(squared / variance, 1.5) << "channel " << c;
    ::testing::Test::RecordProperty(std::string("relativeBias") + "RGB"[c], std::to_string(error / count));
  }
}

}  // namespace

// The wave against the reference path tracer, which shares none of its sampling, in every configuration
// the wave treats differently (tracerCases): the two means of each 8 × 8 block and channel within 4.5
// standard errors. At these samples a block's test catches a bias of 1–18 % with 99 % probability (the
// figures are printed); tests/sweep/tracer_sweep_test.cpp runs the same cases with the samples to catch
// 1 % per 16 × 16 block.
TEST(Integrator, TheWaveMatchesTheReferencePathTracerBlockByBlock) {
  for (const TracerCase& c : tracerCases()) {
    const BlockCheck check = compareTracers(c, 64, 8);
    EXPECT_LT(check.worstZ, 4.5) << c.name;
    EXPECT_GT(check.lit, 0) << c.name << ": a black image proves nothing";
    EXPECT_LE(check.worstDetectable, 0.2) << c.name << ": too few samples to catch a bias of 20 %";
  }
}

// A Lambertian floor under a constant environment and a square lamp whose back hides part of the sky:
// E = Le·Ω⊥(lamp) + L_env·(π − Ω⊥(lamp)), Ω⊥ the lamp's projected solid angle (Lambert's polygon formula).
// Light samples of either light and BSDF samples that find either are weighted by MIS against each other,
// counting the first vertex's light samples: one, three (a split pattern that is no grid) and the default.
class LightSamples : public ::testing::TestWithParam<int> {};

TEST_P(LightSamples, AnEnvironmentAndAnEmitterTogetherGiveTheirAnalyticIrradiance) {
  const Rgb emission(10.0, 5.0, 2.0), sky(0.3, 0.6, 0.9);
  const LampOverFloor stage(emission);
  const Environment environment = Environment::constant(sky);
  // Two independent halves: their difference measures each pixel's noise, which here is mostly the
  // lamp's (the sky's power, over the scene's bounds, is chosen far more often).
  RenderSettings settings = quiet(LampOverFloor::kSize, LampOverFloor::kSize, 2048, 1);
  settings.maxDepth = 2;
  settings.lightSamples = GetParam();
  const RgbImage a = renderScene(stage.description, stage.brdfs, &environment, stage.camera, settings);
  settings.seed = 2;
  const RgbImage b = renderScene(stage.description, stage.brdfs, &environment, stage.camera, settings);
  expectUnbiased(a, b, LampOverFloor::checked, [&](int x, int y, int c) {
    double omega = 0.0;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        omega += projectedSolidAngle(stage.lamp, LampOverFloor::floorPoint(x + (i + 0.5) / 8, y + (j + 0.5) / 8)) / 64;
    return (emission[c] * omega + sky[c] * (kPi - omega)) * (0.5 / kPi);
  });
}

// The same floor and lamp under a map of small bright panels (render_fixtures.h), whose light samples are
// drawn within each cell by its bilinear function: E = Le·Ω⊥(lamp) + ∫ L_env cos θ dω over the sky the
// lamp leaves, that is the map's whole upper hemisphere (a fine midpoint rule in u, v) less what lies
// behind the lamp (a midpoint rule over the lamp's area, dω cos θ = dA / r⁴ for a lamp at height 1 facing
// down). One half from the wave, the other from the reference path tracer. The map's light samples toward
// the floor are drawn from the cells its normal's bin weighs by their cosine bound (cosine_bins.h).
TEST_P(LightSamples, AMapOfBrightPanelsAndAnOccludingEmitterGiveTheirIrradiance) {
  const Rgb emission(2.0, 3.0, 4.0);
  const LampOverFloor stage(emission);
  const TempDir dir;
  writePanelsMap(dir / "panels.exr", 48, 25);
  const Environment environment = Environment::load(dir / "panels.exr");

  Rgb hemisphere(0.0);
  const int nu = 48 * 16, nv = 24 * 16;
  for (int j = 0; j < nv / 2; ++j) {
    const double theta = kPi * (j + 0.5) / nv, dOmega = 2.0 * kPi * kPi * std::sin(theta) / (double(nu) * nv);
    for (int i = 0; i < nu; ++i) {
      const double phi = 2.0 * kPi * (i + 0.5) / nu;
      const Vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      hemisphere += environment.radiance(d) * (d.y * dOmega);
    }
  }
  const auto behindLamp = [&](const glm::dvec3& p) {
    constexpr int n = 32;
    const double side = 2.0 * LampOverFloor::kHalf / n;
    Rgb sum(0.0);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) {
        const glm::dvec3 q(-LampOverFloor::kHalf + (i + 0.5) * side, 1.0, -LampOverFloor::kHalf + (k + 0.5) * side);
        const double r2 = glm::dot(q - p, q - p);
        sum += environment.radiance(glm::normalize(q - p)) * (side * side / (r2 * r2));
      }
    return sum;
  };

  RenderSettings settings = quiet(LampOverFloor::kSize, LampOverFloor::kSize, 1024, 3);
  settings.maxDepth = 2;
  settings.lightSamples = GetParam();
  const RgbImage a = renderScene(stage.description, stage.brdfs, &environment, stage.camera, settings);
  settings.seed = 4;
  settings.reference = true;
  const RgbImage b = renderScene(stage.description, stage.brdfs, &environment, stage.camera, settings);
  expectUnbiased(a, b, LampOverFloor::checked, [&](int x, int y, int c) {
    double omega = 0.0, hidden = 0.0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const glm::dvec3 p = LampOverFloor::floorPoint(x + (i + 0.5) / 4, y + (j + 0.5) / 4);
        omega += projectedSolidAngle(stage.lamp, p) / 16;
        hidden += behindLamp(p)[c] / 16;
      }
    return (emission[c] * omega + hemisphere[c] - hidden) * (0.5 / kPi);
  });
}

INSTANTIATE_TEST_SUITE_P(Integrator, LightSamples, ::testing::Values(1, 3, RenderSettings{}.lightSamples));

// The light samples a first vertex takes follow its BRDF: all of them for a Lambertian one, one for a lobe
// a few milliradians wide, counts between for lobes between; and always one of the few levels.
TEST(LightCount, BroadLobesTakeMoreLightSamplesThanSharpOnes) {
  EXPECT_EQ(lightCountLevels(8), 0b10001011u);  // 1, 2, 4, 8
  EXPECT_EQ(lightCountLevels(3), 0b111u);       // 1, 2, 3
  EXPECT_EQ(lightCountLevels(1), 1u);
  EXPECT_NEAR(lightCarriedShare(Lambertian{Rgb(0.5)}), 0.5, 1e-9);
  EXPECT_EQ(lightSamplesFor(Lambertian{Rgb(0.5)}, 8), 8);
  EXPECT_EQ(lightSamplesFor(Lambertian{Rgb(0.5)}, 3), 3);
  const Brdf sharp = CookTorrance{Rgb(0.02), Rgb(0.2), 0.0125, 1.7};  // a polished metal (steel's E2 fit)
  EXPECT_EQ(lightSamplesFor(sharp, 8), 1);
  // BSDF samples the other way round: several for the sharp lobe, one for the broad ones.
  EXPECT_EQ(bsdfSamplesFor(sharp, true), kMaxBsdfSamples);
  EXPECT_EQ(bsdfSamplesFor(sharp, false), kTracedBsdfSamples);
  for (const bool resampled : {true, false}) {
    EXPECT_EQ(bsdfSamplesFor(Lambertian{Rgb(0.5)}, resampled), 1);
    EXPECT_EQ(bsdfSamplesFor(CookTorrance{Rgb(0.1), Rgb(0.4), 0.3, 1.5}, resampled), 1);
  }
  // A sheet that chooses its spp gives all its panels eight where one of them is sharp.
  EXPECT_EQ(sheetBsdfSamples(std::vector<Brdf>{Lambertian{Rgb(0.5)}, sharp}), kSheetBsdfSamples);
  EXPECT_EQ(sheetBsdfSamples(std::vector<Brdf>{Lambertian{Rgb(0.5)}, Lambertian{Rgb(0.2)}}), 1);
  int last = 8;
  for (const double m : {0.5, 0.2, 0.1, 0.05, 0.02}) {  // a plastic: the lobe narrows, the count does not rise
    const int k = lightSamplesFor(CookTorrance{Rgb(0.1), Rgb(0.4), m, 1.5}, 8);
    EXPECT_LE(k, last) << "m " << m;
    last = k;
  }
  EXPECT_LT(last, 8);
}

namespace {

// The floor under the lamp, rendered (two seeds each) with each BRDF's own counts and with the most light
// samples and one BSDF sample everywhere: the two means agree within four standard errors in each channel.
void expectOwnCountsUnbiased(const LampOverFloor& stage, const Environment& environment, RenderSettings settings) {
  const Camera camera = perspective({0, 2.5, 3}, {0, 0, 0}, 0.9);  // the lamp's highlight on the floor
  settings.lightSamples = kMaxLightSamples;
  const auto image = [&](bool perBrdf, uint32_t seed) {
    settings.lightSamplesPerBrdf = perBrdf;
    settings.seed = seed;
    return renderScene(stage.description, stage.brdfs, &environment, camera, settings);
  };
  const RgbImage a1 = image(true, 1), a2 = image(true, 2), b1 = image(false, 3), b2 = image(false, 4);
  for (int c = 0; c < 3; ++c) {
    double difference = 0.0, variance = 0.0, mean = 0.0;
    for (int y = 0; y < a1.height; ++y)
      for (int x = 0; x < a1.width; ++x) {
        const double ha = 0.5 * (a1.at(x, y)[c] - a2.at(x, y)[c]), hb = 0.5 * (b1.at(x, y)[c] - b2.at(x, y)[c]);
        difference += 0.5 * (a1.at(x, y)[c] + a2.at(x, y)[c]) - 0.5 * (b1.at(x, y)[c] + b2.at(x, y)[c]);
        variance += ha * ha + hb * hb;
        mean += 0.5 * (b1.at(x, y)[c] + b2.at(x, y)[c]);
      }
    ASSERT_GT(mean, 0.0);
    EXPECT_LT(std::abs(difference) / std::sqrt(variance), 4.0) << "channel " << c << ": relative difference " << difference / mean;
  }
}

}  // namespace

// The bias a wrong count would bring shows where a vertex takes fewer light samples than the most: a glossy
// floor under the lamp and a constant sky, rendered with its own count (between 1 and the most) and with
// the most everywhere, converges to the same image. MIS must weigh the light samples and the BSDF sample
// by the count taken at that vertex; weighing either by another count biases the lamp's highlight.
TEST(LightCount, AVertexsOwnCountLeavesTheImageUnbiased) {
  const Rgb emission(10.0, 5.0, 2.0);
  LampOverFloor stage(emission);
  stage.brdfs[0] = CookTorrance{Rgb(0.1), Rgb(0.4), 0.3, 1.5};  // two light samples of the eight
  const int own = lightSamplesFor(stage.brdfs[0], kMaxLightSamples);
  ASSERT_GT(own, 1);
  ASSERT_LT(own, kMaxLightSamples);
  const Environment environment = Environment::constant(Rgb(0.3, 0.6, 0.9));
  RenderSettings settings = quiet(LampOverFloor::kSize, LampOverFloor::kSize, 512, 1);
  settings.maxDepth = 2;
  expectOwnCountsUnbiased(stage, environment, settings);
}

// The same for the BSDF samples of a sharp lobe (light_count.h: several, one light sample): a polished
// floor mirrors the lamp (the BSDF samples that hit it add its emission, each traced as a surface emits)
// under a map of bright panels (those that leave the scene add the map's), rendered with its own counts
// and with one BSDF sample and the most light samples; the two converge to the same image only if each of
// the n is weighed by the counts taken and by 1/n.
TEST(LightCount, ASharpLobesBsdfSamplesLeaveTheImageUnbiased) {
  const Rgb emission(10.0, 5.0, 2.0);
  LampOverFloor stage(emission);
  stage.brdfs[0] = CookTorrance{Rgb(0.02), Rgb(0.4), 0.05, 1.7};
  ASSERT_EQ(bsdfSamplesFor(stage.brdfs[0], false), kTracedBsdfSamples);
  ASSERT_EQ(lightSamplesFor(stage.brdfs[0], kMaxLightSamples), 1);
  const TempDir dir;
  writePanelsMap(dir / "panels.exr", 48, 25);
  const Environment environment = Environment::load(dir / "panels.exr");
  RenderSettings settings = quiet(LampOverFloor::kSize, LampOverFloor::kSize, 256, 1);
  settings.maxDepth = 3;
  expectOwnCountsUnbiased(stage, environment, settings);  // the camera sees the lamp's mirror image
}

// Where no surface emits, the sharp lobe's further BSDF samples are resampled and only the chosen one's ray
// traced (Paths::addOtherBsdfSamples). The plate over the floor is dark here, and a dark wall stands behind
// it, occluders: about their mirror images' edges some of a vertex's samples see the map and some the
// occluder, so the chosen ray's verdict stands for the others'. The image converges to the one rendered
// with one BSDF sample and the most light samples.
TEST(LightCount, AResampledSharpLobeLeavesTheImageUnbiased) {
  LampOverFloor stage(Rgb(0.0));
  stage.description.meshes.push_back(quad({-3, 0, -1}, {6, 0, 0}, {0, 1.5, 0}, 1));
  stage.brdfs[0] = CookTorrance{Rgb(0.02), Rgb(0.4), 0.05, 1.7};
  ASSERT_EQ(bsdfSamplesFor(stage.brdfs[0], true), kMaxBsdfSamples);
  const TempDir dir;
  writePanelsMap(dir / "panels.exr", 48, 25);
  const Environment environment = Environment::load(dir / "panels.exr");
  ASSERT_FALSE(LightSet(LightSources{stage.description, &environment, 10.0}).onSurfaces());
  RenderSettings settings = quiet(LampOverFloor::kSize, LampOverFloor::kSize, 256, 1);
  settings.maxDepth = 3;
  expectOwnCountsUnbiased(stage, environment, settings);  // the camera sees the plate's mirror image
}

TEST(Integrator, TheLightChooserDrawsByPower) {
  SceneDescription description;
  description.materials = {material("dim", Rgb(0.0), Rgb(1.0)), material("bright", Rgb(0.0), Rgb(3.0))};
  description.meshes.push_back(quad({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 0));
  description.meshes.push_back(quad({0, 2, 0}, {2, 0, 0}, {0, 0, 1}, 1));  // twice the area, thrice the radiance
  const Environment environment = Environment::constant(Rgb(0.5));
  const double radius = 2.0;
  const LightSet lights(LightSources{description, &environment, radius});
  // Powers: π·A·L per triangle (4 of area ½, ½, 1, 1), and π r² · 4π · L for the environment.
  const double dim = kPi * 0.5, bright = kPi * 1.0 * 3.0, env = kPi * radius * radius * 4.0 * kPi * 0.5;
  const double total = 2 * dim + 2 * bright + env;
  ASSERT_EQ(lights.distant().size(), 1u);
  EXPECT_NEAR(lights.distant()[0].probability, env / total, 1e-12);
  Hit hit;
  hit.mesh = 1;
  hit.triangle = 1;
  EXPECT_NEAR(lights.at(hit).probability, bright / total, 1e-12);
  hit.mesh = 0;
  EXPECT_NEAR(lights.at(hit).probability, dim / total, 1e-12);
  int chosenEnvironment = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) chosenEnvironment += lights.choose((i + 0.5) / n).light->distant();
  EXPECT_NEAR(double(chosenEnvironment) / n, env / total, 1e-4);
}

// The preview scene and a lamp, scaled with its camera by 1e-3 and 1e3: the same image within noise (the
// regression tests' mean and block z-tests against the unscaled render). Ray offsets that do not scale
// with the scene show here as acne, light leaks or lost contact shadows.
TEST(Integrator, AScaledSceneRendersTheSameImage) {
  const std::filesystem::path scenePath = std::filesystem::path(GLOSSY_SOURCE_DIR) / "scenes/preview.gltf";
  const SceneDescription original = loadGltf(scenePath);
  const Environment sky = Environment::makeDefault();
  auto scaled = [&](double s, Camera& camera) {
    SceneDescription d = original;
    d.materials.push_back(material("lamp", Rgb(0.0), Rgb(6.0)));
    d.meshes.push_back(quad({-0.6f, 1.6f, -0.6f}, {1.2f, 0, 0}, {0, 0, 1.2f}, int(d.materials.size()) - 1));
    for (Mesh& m : d.meshes)
      for (glm::vec3& p : m.positions) p = glm::vec3(glm::dvec3(p) * s);
    camera = d.cameras.front();
    camera.cameraToWorld[3] = glm::dvec4(glm::dvec3(camera.cameraToWorld[3]) * s, 1.0);
    return d;
  };
  const auto brdfs = [](const SceneDescription& d) {
    std::vector<Brdf> b(d.materials.size(), Brdf(CookTorrance{Rgb(0.1, 0.08, 0.05), Rgb(0.8, 0.6, 0.4), 0.12, 1.6}));
    b.back() = Lambertian{Rgb(0.0)};
    return b;
  };
  Camera camera;
  const SceneDescription unit = scaled(1.0, camera);
  const int size = 48, referenceSpp = 256, halfSpp = 64;
  const RgbImage reference = renderScene(unit, brdfs(unit), &sky, camera, quiet(size, size, referenceSpp, 7));
  const std::vector<char> mask(size_t(size) * size, 1);
  for (double s : {1e-3, 1e3}) {
    const SceneDescription d = scaled(s, camera);
    const RgbImage a = renderScene(d, brdfs(d), &sky, camera, quiet(size, size, halfSpp, 11));
    const RgbImage b = renderScene(d, brdfs(d), &sky, camera, quiet(size, size, halfSpp, 12));
    const ImageComparison result = compareWithReference(a, b, halfSpp, reference, referenceSpp, mask, 1e-3);
    EXPECT_TRUE(result.passed) << "scale " << s << ": " << result.message;
    RecordProperty("relativeBias" + std::to_string(int(std::log10(s))), std::to_string(result.relativeBias));
  }
}

// A lamp 1e-5 above a floor, facing it, at scale 1: a ray slipping under its edge finds the floor lit by
// nearly the whole hemisphere of it (Lambert's formula for the rectangle). Offsets larger than the gap
// would start the light's shadow rays and the floor's BSDF rays above the lamp.
TEST(Integrator, ALightJustAboveASurfaceStillLightsIt) {
  const float gap = 1e-5f;
  SceneDescription description;
  description.materials = {material("floor"), material("lamp", Rgb(0.0), Rgb(2.0))};
  description.meshes.push_back(quad({-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, 0));
  description.meshes.push_back(quad({0, gap, -1}, {1, 0, 0}, {0, 0, 2}, 1));  // x in [0, 1], facing down
  const std::vector<Brdf> brdfs = {Lambertian{Rgb(0.5)}, Lambertian{Rgb(0.0)}};
  // An orthographic pixel far smaller than the gap, its ray passing under the lamp's edge at x = 0 to
  // reach the floor at x = 5e-4.
  const glm::dvec3 eye(-1e-3, 0.5 * gap, 0.0), floorPoint(5e-4, 0.0, 0.0);
  const Camera camera = orthographicDown(1e-9, eye, floorPoint, {0, 1, 0});
  RenderSettings settings = quiet(1, 1, 1 << 14);
  settings.maxDepth = 2;
  const RgbImage img = renderScene(description, brdfs, nullptr, camera, settings);
  const Vec3 corners[4] = {{0, gap, -1}, {1, gap, -1}, {1, gap, 1}, {0, gap, 1}};
  const double omega = projectedSolidAngle(corners, floorPoint);
  const double want = 2.0 * omega * 0.5 / kPi;
  ASSERT_GT(omega, 0.99 * kPi);
  EXPECT_NEAR(img.at(0, 0)[0], want, 0.01 * want);
}

// A pixel mask (a sheet's noise-floor row renders only the object's pixels): the marked pixels are the
// full render's, each its own samples in order (up to rounding where a wave's paths rejoin their sums),
// the others stay black and cost nothing.
TEST(Integrator, APixelMaskRendersOnlyItsPixels) {
  const Environment sky = Environment::makeDefault();
  const SphereOnFloor stage(CookTorrance{Rgb(0.1, 0.08, 0.05), Rgb(0.8, 0.6, 0.4), 0.12, 1.6}, true);
  const Camera camera = perspective({0, 1.5, 5}, {0, 0, 0}, 0.7);
  RenderSettings settings = quiet(40, 32, 9);
  const RgbImage whole = renderScene(stage.description, stage.brdfs, &sky, camera, settings);
  std::vector<char> mask(size_t(40 * 32));
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = (i / 3 + i / 40) % 2;  // stripes, across tile edges
  settings.pixels = &mask;
  const RgbImage part = renderScene(stage.description, stage.brdfs, &sky, camera, settings);
  size_t lit = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 40; ++x)
      for (int c = 0; c < 3; ++c) {
        const float want = mask[size_t(y * 40 + x)] ? whole.at(x, y)[c] : 0.0f;
        EXPECT_NEAR(part.at(x, y)[c], want, 1e-5f * std::max(1.0f, whole.at(x, y)[c])) << x << "," << y;
        lit += want > 0.0f;
      }
  EXPECT_GT(lit, 1000u);
  mask.pop_back();
  EXPECT_THROW(renderScene(stage.description, stage.brdfs, &sky, camera, settings), std::invalid_argument);
}

}  // namespace glossy::test
