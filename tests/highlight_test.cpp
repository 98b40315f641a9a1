// A sharp lobe reflecting a small bright light, the case glossy exists for and the one where a wrong
// environment lookup, sampling table or MIS weight shows most: a polished floor seen by an orthographic
// camera, under a lat-long map of a dim background with a 2 × 2-texel source of radiance 2000. Every pixel
// sees the same view direction V, so each pixel is an estimate of one number, the reflected radiance
//     L_o(V) = ∫ ρ(ω, V) cos θ L(ω) dω,
// which a quadrature computes without the renderer: the source's bilinear footprint (docs/rendering.md's
// texel convention, the same as Mitsuba 3's envmap) summed over 48 × 48 points per texel, plus the
// background times the directional albedo. The image must carry that light within a few percent, over
// several seeds, for the analytic models, GGX and measured data, at the lobe's peak, beside it and at a
// grazing view, and every estimator (the wave, the reference, cosine sampling with eight light samples,
// one light and one BSDF sample, a sheet's panels) must agree with it.
#include "materials/core/lane_math.h"
#include "materials/merl/merl_table.h"
#include "materials/params/material_file.h"
#include "renderer/image/exr_image.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/lights/environment.h"
#include "renderer/scene/embree_scene.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace glossy::test {

namespace {

constexpr int kMapWidth = 512, kMapHeight = 256;
constexpr double kBackground = 0.1, kSource = 2000.0;

// The source's top-left texel; it covers (column, row) to (column + 1, row + 1).
struct SourcePlace {
  int column, row;
};

// The direction of lookup coordinates (x, y) (x = u·W − ½, y = v·(H − 1)), by the spec's formulas.
Vec3 directionAt(double x, double y) {
  const double u = (x + 0.5) / kMapWidth, v = y / (kMapHeight - 1);
  const double theta = kPi * v, phi = 2.0 * kPi * u;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// The centre of the source's light: its bilinear footprint is symmetric about the middle of its texels.
Vec3 sourceCentre(SourcePlace s) { return directionAt(s.column + 0.5, s.row + 0.5); }

void writeSourceMap(const std::filesystem::path& path, SourcePlace s) {
  RgbImage map(kMapWidth, kMapHeight);
  for (float& p : map.pixels) p = float(kBackground);
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx)
      for (int c = 0; c < 3; ++c) map.at(s.column + dx, s.row + dy)[c] = float(kSource);
  writeExr(path, map, {});
}

// The floor's local frame: the BRDF's z is world +Y (isotropic models: the azimuth's origin is free).
Vec3 toLocal(const Vec3& w) { return {w.x, -w.z, w.y}; }

// L_o(V) by quadrature, independent of the renderer: the background's part from the directional albedo
// (a midpoint rule, coarse for a sharp lobe but carrying under 0.1 % of the light here), the source's
// excess over the background from its bilinear footprint (texels column − 1 … column + 2 around it).
Rgb expectedRadiance(const Brdf& brdf, const Vec3& V, SourcePlace s) {
  const Vec3 v = toLocal(V);
  Rgb sum = directionalAlbedo(brdf, v) * kBackground;
  constexpr int kPoints = 48;  // per texel and axis
  const auto texel = [&](int x, int y) { return x >= s.column && x <= s.column + 1 && y >= s.row && y <= s.row + 1; };
  const double cellSolidAngle = (2.0 * kPi / kMapWidth) * (kPi / (kMapHeight - 1)) / (kPoints * kPoints);
  for (int i = 0; i < 3 * kPoints; ++i)
    for (int j = 0; j < 3 * kPoints; ++j) {
      const double x = s.column - 1 + (i + 0.5) / kPoints, y = s.row - 1 + (j + 0.5) / kPoints;
      const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
      const double fx = x - x0, fy = y - y0;
      const double excess = (kSource - kBackground) * ((1 - fx) * (1 - fy) * texel(x0, y0) + fx * (1 - fy) * texel(x0 + 1, y0) +
                                                       (1 - fx) * fy * texel(x0, y0 + 1) + fx * fy * texel(x0 + 1, y0 + 1));
      if (excess <= 0.0) continue;
      const Vec3 w = directionAt(x, y);
      const Vec3 l = toLocal(w);
      if (l.z <= 0.0) continue;
      const double sinTheta = std::sin(kPi * y / (kMapHeight - 1));
      sum += eval(brdf, l, v) * (l.z * excess * sinTheta * cellSolidAngle);
    }
  return sum;
}

// How a render is made: the estimators glossy has for this light.
enum class Estimator { Wave, Reference, CosineEightLights, OneAndOne, SheetPanel };

const char* name(Estimator e) {
  switch (e) {
    case Estimator::Wave: return "the wave (its own counts)";
    case Estimator::Reference: return "the reference";
    case Estimator::CosineEightLights: return "cosine sampling, eight light samples";
    case Estimator::OneAndOne: return "one light and one BSDF sample";
    case Estimator::SheetPanel: return "a sheet's panel";
  }
  return "";
}

struct Floor {
  SceneDescription description;
  EmbreeScene bvh;
  Floor() : description(make()), bvh(description) {}
  static SceneDescription make() {
    SceneDescription d;
    d.materials = {material("floor")};
    d.meshes.push_back(quad({-4, 0, -4}, {0, 0, 8}, {8, 0, 0}, 0));  // facing +Y
    return d;
  }
};

constexpr int kPixels = 24, kSpp = 64;

// The mean of the floor's pixels, per channel, and its standard error (the pixels are independent).
struct Estimate {
  Rgb mean{0.0}, standardError{0.0};
};

Estimate renderFloor(const Floor& floor, const Brdf& brdf, const Environment& environment, const Vec3& V, Estimator e,
                     uint32_t seed) {
  const Camera camera = orthographicDown(0.02, V * 3.0, Vec3(0.0), std::abs(V.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(0, 0, -1));
  RenderSettings settings;
  settings.width = settings.height = kPixels;
  settings.spp = kSpp;
  settings.seed = seed;
  settings.threads = 2;
  settings.progress = false;
  settings.maxDepth = 3;
  settings.reference = e == Estimator::Reference;
  if (e == Estimator::CosineEightLights || e == Estimator::OneAndOne || e == Estimator::SheetPanel) {
    settings.lightSamplesPerBrdf = false;
    settings.lightSamples = e == Estimator::CosineEightLights ? 8 : 1;
    settings.bsdfSamples = 1;
  }
  settings.cosineBrdfSampling = e == Estimator::CosineEightLights;
  RenderStats stats;
  RgbImage image;
  const RenderScene scene{&floor.description, &floor.bvh, {brdf}, Lambertian{Rgb(0.5)}, &environment};
  if (e == Estimator::SheetPanel) {
    // The floor is the object; a second, Lambertian panel shares its draws, as a sheet's panels do.
    RenderScene panels[2] = {scene, scene};
    panels[0].objectMeshes = panels[1].objectMeshes = {true};
    panels[1].brdfs = {Lambertian{Rgb(0.5)}};
    image = renderPanels(panels, camera, settings, stats)[0];
  } else {
    image = render(scene, camera, settings, stats);
  }
  Estimate out;
  const double n = double(kPixels) * kPixels;
  for (int c = 0; c < 3; ++c) {
    double s = 0.0, s2 = 0.0;
    for (int y = 0; y < kPixels; ++y)
      for (int x = 0; x < kPixels; ++x) {
        const double p = image.at(x, y)[c];
        s += p;
        s2 += p * p;
      }
    out.mean[c] = s / n;
    out.standardError[c] = std::sqrt(std::max(0.0, s2 / n - out.mean[c] * out.mean[c]) / (n - 1));
  }
  return out;
}

struct HighlightCase {
  std::string label;
  Brdf brdf;
};

Brdf libraryFit(const std::string& material, const std::string& fit) {
  const MaterialFile file = loadMaterialFile(libraryDir() / "merl" / (material + ".toml"));
  const Fit* f = file.find(FitId::parse(fit, "test"));
  if (!f) throw std::runtime_error(material + " has no fit " + fit);
  return makeBrdf(*f);
}

// The views: V the mirror image of the source's centre (the lobe's peak), V turned 0.8° about +Y (beside
// it: the lobe's flank, where a half-texel shift of the map shows), and a source 12° above the horizon
// seen at its mirror angle (grazing).
struct View {
  const char* label;
  SourcePlace source;
  double turnDegrees;
};
constexpr View kViews[] = {{"peak", {218, 79}, 0.0}, {"beside the peak", {218, 79}, 0.8}, {"grazing", {300, 110}, 0.0}};

Vec3 viewFor(const View& view) {
  const Vec3 c = sourceCentre(view.source);
  const Vec3 mirror(-c.x, c.y, -c.z);
  const double a = view.turnDegrees * kPi / 180.0;
  return {mirror.x * std::cos(a) + mirror.z * std::sin(a), mirror.y, -mirror.x * std::sin(a) + mirror.z * std::cos(a)};
}

// The image's light against the quadrature's, per seed and pooled, for each estimator: within 3 % pooled
// (and 4 standard errors beyond that), and each seed within 3 % plus 4 of its standard errors.
void expectCarriesTheLight(const HighlightCase& c, std::initializer_list<Estimator> estimators) {
  const TempDir dir;
  const Floor floor;
  for (const View& view : kViews) {
    writeSourceMap(dir / "source.exr", view.source);
    const Environment environment = Environment::load(dir / "source.exr");
    const Vec3 V = viewFor(view);
    ASSERT_GT(V.y, 0.15) << view.label;
    const Rgb expected = expectedRadiance(c.brdf, V, view.source);
    const double want = luminance(expected);
    ASSERT_GT(want, 20.0 * kBackground) << c.label << ", " << view.label << ": the source must dominate";
    for (const Estimator e : estimators) {
      double pooled = 0.0, pooledVariance = 0.0;
      constexpr int kSeeds = 4;
      for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
        const Estimate got = renderFloor(floor, c.brdf, environment, V, e, seed);
        const double mean = luminance(got.mean);
        const double se = luminance(got.standardError);
        pooled += mean / kSeeds;
        pooledVariance += se * se / (kSeeds * kSeeds);
        EXPECT_NEAR(mean / want, 1.0, 0.03 + 4.0 * se / want)
            << c.label << ", " << view.label << ", " << name(e) << ", seed " << seed << ": " << mean << " against " << want;
      }
      EXPECT_NEAR(pooled / want, 1.0, 0.03 + 4.0 * std::sqrt(pooledVariance) / want)
          << c.label << ", " << view.label << ", " << name(e) << ", " << kSeeds << " seeds: " << pooled << " against " << want;
      ::testing::Test::RecordProperty(c.label + " " + view.label + " " + name(e), std::to_string(pooled / want));
    }
  }
}

constexpr std::initializer_list<Estimator> kAll = {Estimator::Wave, Estimator::Reference, Estimator::CosineEightLights,
                                                    Estimator::OneAndOne, Estimator::SheetPanel};

}  // namespace

TEST(Highlight, CookTorranceCarriesTheLightOfASmallSource) {
  expectCarriesTheLight({"ss440 CT E2 (m = 0.0136)", libraryFit("ss440", "cook-torrance:E2")}, kAll);
}

// The map's lookups and the models' batches call libmvec's AVX2 variants where the CPU has them, its SSE2
// ones elsewhere (lane_math.h): the highlight must not depend on which.
TEST(Highlight, TheBaselineVectorPathCarriesTheSameLight) {
  const lanes::Isa saved = lanes::isa();
  ASSERT_TRUE(lanes::setIsa(lanes::Isa::Sse2));
  expectCarriesTheLight({"ss440 CT E2 (m = 0.0136), SSE2", libraryFit("ss440", "cook-torrance:E2")}, {Estimator::Wave});
  lanes::setIsa(saved);
}

TEST(Highlight, EveryModelCarriesTheLightOfASmallSource) {
  for (const auto& [material, fit] : std::vector<std::pair<std::string, std::string>>{
           {"hematite", "cook-torrance:E2"}, {"chrome", "microfacet:E2"}, {"chrome", "smooth:E2"},
           {"chrome", "ashikhmin-shirley:E2"}, {"steel", "microfacet:E2"}})
    expectCarriesTheLight({material + " " + fit, libraryFit(material, fit)}, {Estimator::Wave, Estimator::OneAndOne});
  expectCarriesTheLight({"GGX α = 0.01", Ggx{Rgb(0.01), Rgb(0.9, 0.8, 0.7), 0.01, 1.8}},
                        {Estimator::Wave, Estimator::OneAndOne, Estimator::CosineEightLights});
}

TEST(Highlight, MeasuredDataCarryTheLightOfASmallSource) {
  GLOSSY_REQUIRE_SHARED("merl/chrome.binary.xz");
  const auto table = std::make_shared<const MerlTable>(MerlTable::load(sharedDir() / "merl" / "chrome.binary.xz"));
  expectCarriesTheLight({"chrome, MERL (NBRDF reconstruction)", Measured(table)}, {Estimator::Wave, Estimator::OneAndOne});
}

}  // namespace glossy::test
