// The path tracer end to end, on scenes built here: a white furnace, directional albedo per pixel of an
// orthographic sphere against an independent quadrature, an emissive quad against its analytic irradiance,
// the environment's orientation as a camera sees it, determinism, and no NaN/Inf for the supplement fits.
#include "materials/params/material_file.h"
#include "renderer/integrator/path_tracer.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/test_support.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace glossy::test {

namespace {

struct Fixture {
  SceneDescription description;
  std::vector<Brdf> brdfs;
  Environment environment = Environment::constant(Rgb(1.0));
  bool withEnvironment = true;  // false: a scene lit by its emitters alone (RenderScene::environment null)

  RgbImage renderWith(const Camera& camera, const RenderSettings& settings, RenderStats* statsOut = nullptr) {
    const EmbreeScene bvh(description);
    const RenderScene scene{&description, &bvh, brdfs, Lambertian{Rgb(0.5)}, withEnvironment ? &environment : nullptr};
    RenderStats stats;
    RgbImage image = render(scene, camera, settings, stats);
    if (statsOut) *statsOut = stats;
    return image;
  }
};

RenderSettings quiet(int size, int spp) {
  RenderSettings s;
  s.width = s.height = size;
  s.spp = spp;
  s.progress = false;
  return s;
}


}  // namespace

TEST(Render, WhiteFurnace) {
  Fixture f;
  f.description.materials.push_back(material("white", Rgb(1.0)));
  f.description.meshes.push_back(uvSphere(1.0, 96, 48, 0));
  f.brdfs.push_back(Lambertian{Rgb(1.0)});
  RenderStats stats;
  const RgbImage img = f.renderWith(orthographicDown(1.2, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}), quiet(32, 64), &stats);
  // A closed white Lambertian sphere under radiance 1 returns radiance 1 from every point, whatever the
  // number of bounces — within noise and Russian roulette's variance.
  double sum = 0.0, worst = 0.0;
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    sum += img.pixels[i];
    worst = std::max(worst, std::abs(img.pixels[i] - 1.0));
  }
  EXPECT_NEAR(sum / img.pixels.size(), 1.0, 2e-3);
  EXPECT_LT(worst, 0.05);
  EXPECT_EQ(stats.droppedSamples, 0u);
}

TEST(Render, OrthographicSphereShowsTheDirectionalAlbedoOfEachPixelsViewAngle) {
  // Each checked pixel is its own orthographic view with a footprint far smaller than the curvature, so
  // its view angle is exact. 2^18 samples put the noise at ≤ 0.15 % (measured σ = 0.6 % at 16384 spp for
  // the noisiest case, 70°), so the 1 % tolerance is > 6σ yet fails on a 1 % bias.
  // Broad fits, so that the independent midpoint-rule reference resolves their lobes; narrow lobes are
  // checked at the sphere's centre against the spec's table (SphereCentreShowsTheSpecsReferenceAlbedos).
  for (const auto& [name, fit] : {std::pair{"blue-rubber", "cook-torrance:E2"}, std::pair{"gold-paint", "ashikhmin-shirley:E1"},
                                  std::pair{"gold-paint", "microfacet:E2"}, std::pair{"blue-rubber", "smooth:E2"}}) {
    const MaterialFile m = loadMaterialFile(materialsDir() / (std::string(name) + ".toml"));
    const Brdf brdf = makeBrdf(*m.find(FitId::parse(fit, "test")));
    Fixture f;
    f.description.materials.push_back(material("object"));
    f.description.meshes.push_back(uvSphere(1.0, 256, 128, 0));
    f.brdfs.push_back(brdf);
    RenderSettings settings = quiet(1, 1 << 18);
    settings.maxDepth = 2;  // a convex object: light reaches the eye after exactly one reflection
    for (const auto& [thetaDeg, phi] : {std::pair{0.0, 0.0}, std::pair{25.0, 0.4}, std::pair{45.0, 2.6}, std::pair{60.0, 4.0},
                                        std::pair{70.0, 0.4}}) {
      const double r = std::sin(thetaDeg * kPi / 180.0), px = r * std::cos(phi), py = r * std::sin(phi);
      const RgbImage img = f.renderWith(orthographicDown(1e-3, {px, py, 5}, {px, py, 0}, {0, 1, 0}), settings);
      const Rgb want = directionalAlbedo(brdf, Vec3(r, 0.0, std::cos(thetaDeg * kPi / 180.0)));
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(img.at(0, 0)[c], want[c], 0.01 * want[c] + 1e-4) << name << " " << fit << " θv " << thetaDeg << "°";
    }
  }
}

TEST(Render, SphereCentreShowsTheSpecsReferenceAlbedos) {
  // shared/spec/models.md: ∫ρ cos θ_L dω_L at V = N (red) of published fits, as the centre of a sphere
  // seen head-on under radiance 1 shows it. This checks eval, pdf and MIS together on narrow lobes.
  struct Reference {
    const char* material;
    const char* fit;
    double red;
  };
  const Reference refs[] = {
      {"aluminium", "microfacet:E2", 0.1473}, {"aluminium", "smooth:E2", 0.1546}, {"aluminium", "ashikhmin-shirley:E2", 0.1057},
      {"aluminium", "cook-torrance:E2", 0.1053}, {"aluminium", "cook-torrance:E1", 0.1161}, {"aluminium", "ashikhmin-shirley:E1", 0.1167},
      {"black-obsidian", "microfacet:E2", 0.0088}, {"black-obsidian", "smooth:E2", 0.0077}, {"black-obsidian", "ashikhmin-shirley:E2", 0.0075},
      {"black-obsidian", "cook-torrance:E2", 0.0075}, {"black-obsidian", "cook-torrance:E1", 0.0095}, {"black-obsidian", "ashikhmin-shirley:E1", 0.0095},
      {"alum-bronze", "microfacet:E2", 0.1176}, {"alum-bronze", "smooth:E2", 0.1217}, {"alum-bronze", "ashikhmin-shirley:E2", 0.1182},
      {"alum-bronze", "cook-torrance:E2", 0.1174}, {"alum-bronze", "cook-torrance:E1", 0.1147}, {"alum-bronze", "ashikhmin-shirley:E1", 0.1147}};
  for (const Reference& ref : refs) {
    const MaterialFile m = loadMaterialFile(materialsDir() / (std::string(ref.material) + ".toml"));
    Fixture f;
    f.description.materials.push_back(material("object"));
    f.description.meshes.push_back(uvSphere(1.0, 256, 128, 0));
    f.brdfs.push_back(makeBrdf(*m.find(FitId::parse(ref.fit, "test"))));
    RenderSettings settings = quiet(1, 16384);
    settings.maxDepth = 2;
    const RgbImage img = f.renderWith(orthographicDown(1e-3, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}), settings);
    EXPECT_NEAR(img.at(0, 0)[0], ref.red, 0.01 * ref.red + 5e-5) << ref.material << " " << ref.fit;
  }
}

// With no environment at all the packets' environment stages must stand aside: the lamp alone lights the
// floor as brightly as under a black sky (there half the light samples went to the sky).
TEST(Render, EmittersAloneWithoutAnEnvironment) {
  Fixture f;
  f.description.materials.push_back(material("floor", Rgb(0.5)));
  f.description.materials.push_back(material("lamp", Rgb(0.0), Rgb(10.0, 5.0, 2.0)));
  f.description.meshes.push_back(quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0));
  f.description.meshes.push_back(quad({-0.2f, 1, -0.2f}, {0.4f, 0, 0}, {0, 0, 0.4f}, 1));
  f.brdfs = {Lambertian{Rgb(0.5)}, Lambertian{Rgb(0.0)}};
  const Camera cam = orthographicDown(2.0, {0, 5, 0}, {0, 0, 0}, {0, 0, -1});
  RenderSettings settings = quiet(24, 256);
  settings.maxDepth = 2;
  f.withEnvironment = false;
  const RgbImage alone = f.renderWith(cam, settings);
  f.withEnvironment = true;
  f.environment = Environment::constant(Rgb(0.0));
  const RgbImage blackSky = f.renderWith(cam, settings);
  double sumAlone = 0.0, sumBlack = 0.0;
  for (size_t i = 0; i < alone.pixels.size(); ++i) {
    ASSERT_TRUE(std::isfinite(alone.pixels[i]));
    sumAlone += alone.pixels[i];
    sumBlack += blackSky.pixels[i];
  }
  ASSERT_GT(sumBlack, 0.0);
  EXPECT_NEAR(sumAlone / sumBlack, 1.0, 0.02);
}

TEST(Render, EmissiveQuadLightsAPlaneWithItsAnalyticIrradiance) {
  Fixture f;
  f.environment = Environment::constant(Rgb(0.0));
  f.description.materials.push_back(material("floor", Rgb(0.5)));
  f.description.materials.push_back(material("lamp", Rgb(0.0), Rgb(10.0, 5.0, 2.0)));
  f.description.meshes.push_back(quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0));  // floor facing +Y
  // A 0.4 × 0.4 lamp 1 m up, facing down (clockwise seen from above).
  f.description.meshes.push_back(quad({-0.2f, 1, -0.2f}, {0.4f, 0, 0}, {0, 0, 0.4f}, 1));
  f.brdfs = {Lambertian{Rgb(0.5)}, Lambertian{Rgb(0.0)}};
  const Camera cam = orthographicDown(2.0, {0, 5, 0}, {0, 0, 0}, {0, 0, -1});
  RenderSettings settings = quiet(40, 1024);
  settings.maxDepth = 2;
  const RgbImage img = f.renderWith(cam, settings);
  double ratioSum = 0.0;
  // Lambert's polygon formula: E = Le/2 Σ_edges γ_i (n · unit(v_i × v_{i+1})), from the receiving point.
  auto irradiance = [](const Vec3& p) {
    const Vec3 corners[4] = {{-0.2, 1, -0.2}, {0.2, 1, -0.2}, {0.2, 1, 0.2}, {-0.2, 1, 0.2}};
    return projectedSolidAngle(corners, p);
  };
  int checked = 0;
  for (int x : {4, 8, 12, 28, 32, 36})
    for (int y : {4, 12, 20, 28, 36}) {
      // Pixel → floor points (the camera's right is +X, its up −Z); the pixel averages the irradiance over
      // its footprint, so the reference does too.
      auto floorX = [](double px) { return (2.0 * px / 40 - 1.0) * 2.0; };
      auto floorZ = [](double py) { return -(1.0 - 2.0 * py / 40) * 2.0; };
      if (std::abs(floorX(x + 0.5)) < 0.5 && std::abs(floorZ(y + 0.5)) < 0.5) continue;  // the lamp's back hides it
      double e = 0.0;
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) e += irradiance(Vec3(floorX(x + (i + 0.5) / 8), 0, floorZ(y + (j + 0.5) / 8))) / 64;
      const Rgb want = Rgb(10.0, 5.0, 2.0) * (0.5 / kPi * e);
      // Per pixel: within ~4.7σ of the noise at this spp (σ ≈ 0.85 %).
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(x, y)[c], want[c], 0.04 * want[c]) << x << "," << y;
      ratioSum += img.at(x, y)[0] / want[0];
      ++checked;
    }
  EXPECT_GT(checked, 20);
  // Over all pixels a bias of more than ~4σ of the mean shows.
  EXPECT_NEAR(ratioSum / checked, 1.0, 0.006);
}

TEST(Render, TheCameraSeesTheEnvironmentWhereTheConventionPutsIt) {
  // A map black but for one bright column band at u = 0, which the convention puts at −Z, and one at
  // u = 0.25, at +X. A camera at the origin looking down −Z sees the first at its centre; turned to +X it
  // sees the second.
  TempDir tmp;
  RgbImage map(64, 32);
  for (int y = 12; y < 20; ++y) {
    for (int x : {0, 63}) map.at(x, y)[0] = 100.0f;  // u ≈ 0 (wrapping)
    for (int x : {15, 16}) map.at(x, y)[2] = 100.0f; // u ≈ 0.25
  }
  writeExr(tmp / "map.exr", map, {});
  Fixture f;
  f.environment = Environment::load(tmp / "map.exr");
  Camera cam;
  cam.yfov = 0.2;
  RenderSettings s = quiet(9, 4);
  RgbImage img = f.renderWith(cam, s);
  EXPECT_GT(img.at(4, 4)[0], 10.0f);
  EXPECT_EQ(img.at(4, 4)[2], 0.0f);
  cam.cameraToWorld = glm::inverse(glm::lookAt(glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)));
  img = f.renderWith(cam, s);
  EXPECT_GT(img.at(4, 4)[2], 10.0f);
  EXPECT_EQ(img.at(4, 4)[0], 0.0f);
}

TEST(Render, SameSeedSameImageWhateverTheThreadCount) {
  Fixture f;
  f.environment = Environment::makeDefault();
  f.description.materials.push_back(material("object"));
  f.description.meshes.push_back(uvSphere(1.0, 32, 16, 0));
  f.description.meshes.push_back(quad({-3, -1, 3}, {6, 0, 0}, {0, 0, -6}, -1));
  f.brdfs.push_back(CookTorrance{Rgb(0.2), Rgb(0.5), 0.2, 1.5});
  Camera cam;
  cam.cameraToWorld = glm::inverse(glm::lookAt(glm::dvec3(0, 1, 4), glm::dvec3(0), glm::dvec3(0, 1, 0)));
  RenderSettings s = quiet(24, 8);
  s.seed = 5;
  s.threads = 1;
  const RgbImage a = f.renderWith(cam, s);
  s.threads = 2;
  const RgbImage b = f.renderWith(cam, s);
  EXPECT_EQ(a.pixels, b.pixels);
  s.seed = 6;
  EXPECT_NE(a.pixels, f.renderWith(cam, s).pixels);
}

TEST(Render, NoNonFiniteValueForAnyFitOfTheSixSupplementMaterials) {
  for (const std::string& name : supplementMaterials()) {
    const MaterialFile m = loadMaterialFile(materialsDir() / (name + ".toml"));
    for (const Fit& fit : m.fits) {
      Fixture fx;
      fx.environment = Environment::makeDefault();
      fx.description.materials.push_back(material("object"));
      fx.description.meshes.push_back(uvSphere(1.0, 48, 24, 0));
      fx.brdfs.push_back(makeBrdf(fit));
      Camera cam;
      cam.cameraToWorld = glm::inverse(glm::lookAt(glm::dvec3(0, 1, 4), glm::dvec3(0), glm::dvec3(0, 1, 0)));
      RenderStats stats;
      const RgbImage img = fx.renderWith(cam, quiet(16, 4), &stats);
      for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << name << " " << fit.id.str();
      EXPECT_EQ(stats.droppedSamples, 0u) << name << " " << fit.id.str();
    }
  }
}

}  // namespace glossy::test
