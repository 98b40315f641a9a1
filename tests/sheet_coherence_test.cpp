// A sheet's panels rendered together (renderPanels) are each the image a solo render of the panel makes:
// the same paths with the same draws, summed per pixel in another order only where paths stop at the object.
// Where no path meets the object, every panel holds the same bits.
#include "renderer/camera/camera_rays.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/sheet/sheet.h"
#include "tests/support/test_support.h"

#include <cmath>

namespace glossy::test {

namespace {

struct Stage {
  SceneDescription description = loadGltf(sourceDir() / "scenes/preview.gltf");
  EmbreeScene bvh{description};
  Environment environment = Environment::makeDefault();
  SheetScene sheet = makeSheetScene(description, bvh, environment, description.cameras.front());

  RenderScene withObject(const Brdf& brdf) const { return sheet.withObject(brdf); }
};
const Stage& stage() {
  static const Stage s;
  return s;
}

// Three panels as different as the grid gets: a near-mirror, a broad lobe, a diffuse one; with the
// measured table when shared/merl has it.
std::vector<RenderScene> panelScenes() {
  const MaterialFile chrome = loadMaterialFile(materialsDir() / "chrome.toml");
  const MaterialFile rubber = loadMaterialFile(materialsDir() / "blue-rubber.toml");
  std::vector<RenderScene> scenes = {
      stage().withObject(makeBrdf(*chrome.find(FitId::parse("ashikhmin-shirley:E1", "test")))),
      stage().withObject(makeBrdf(*chrome.find(FitId::parse("smooth:E2", "test")))),
      stage().withObject(makeBrdf(*rubber.find(FitId::parse("cook-torrance:E2", "test")))),
  };
  if (std::filesystem::exists(sharedDir() / "merl/gold-paint.binary.xz"))
    scenes.push_back(stage().withObject(Measured(std::make_shared<const MerlTable>(MerlTable::load(sharedDir() / "merl/gold-paint.binary")))));
  return scenes;
}

RenderSettings smallSettings() {
  RenderSettings s;
  s.width = s.height = 40;
  s.spp = 8;
  s.maxDepth = 8;
  s.seed = 7;
  s.threads = 2;
  s.progress = false;
  return s;
}

}  // namespace

// At a sheet's counts (several light and BSDF samples at the object, the same in every panel), each panel
// is the render of its scene alone.
TEST(CoherentPanels, EachPanelIsItsSoloRender) {
  const std::vector<RenderScene> scenes = panelScenes();
  RenderSettings settings = smallSettings();
  settings.lightSamplesPerBrdf = false;
  settings.lightSamples = 4;
  settings.bsdfSamples = 3;
  RenderStats stats;
  const std::vector<RgbImage> together = renderPanels(scenes, stage().description.cameras.front(), settings, stats);
  ASSERT_EQ(together.size(), scenes.size());
  EXPECT_GT(stats.objectPaths, 0u) << "no path reached the object: nothing was tested";
  for (size_t p = 0; p < scenes.size(); ++p) {
    RenderStats soloStats;
    const RgbImage solo = render(scenes[p], stage().description.cameras.front(), settings, soloStats);
    // Each sample's radiance is the solo render's bit for bit; the pixel's sum of them is taken in double
    // in another order, so the float pixel may differ in its last bit, rarely.
    size_t same = 0;
    for (size_t i = 0; i < solo.pixels.size(); ++i) {
      const double a = together[p].pixels[i], b = solo.pixels[i];
      ASSERT_LE(std::abs(a - b), 2e-7 * std::max(std::abs(b), 1e-30)) << "panel " << p << " value " << i;
      same += a == b;
    }
    EXPECT_GE(double(same), 0.999 * double(solo.pixels.size())) << "panel " << p;
  }
}

// The reference path tracer renders each panel as its own scene, with the same random numbers per pixel:
// a sheet's panels by it are, bit for bit, its images of the panels' scenes one at a time.
TEST(CoherentPanels, TheReferenceTracerRendersEachPanelAsItsOwnScene) {
  const std::vector<RenderScene> scenes = panelScenes();
  RenderSettings settings = smallSettings();
  settings.reference = true;
  RenderStats stats;
  const std::vector<RgbImage> together = renderPanels(scenes, stage().description.cameras.front(), settings, stats);
  for (size_t p = 0; p < scenes.size(); ++p) {
    const RgbImage alone = render(scenes[p], stage().description.cameras.front(), settings, stats);
    EXPECT_EQ(together[p].pixels, alone.pixels) << "panel " << p;
  }
  EXPECT_NE(together[0].pixels, together[1].pixels);
}

TEST(CoherentPanels, BackdropIsSharedBitForBitWherePathsMissTheObject) {
  // Depth 2: a backdrop vertex's light sample and its BSDF ray, which may reach the object but is not
  // shaded there; so only pixels whose camera rays can hit the object differ between panels.
  const std::vector<RenderScene> scenes = panelScenes();
  RenderSettings settings = smallSettings();
  settings.maxDepth = 2;
  RenderStats stats;
  const std::vector<RgbImage> images = renderPanels(scenes, stage().description.cameras.front(), settings, stats);
  const Camera& camera = stage().description.cameras.front();
  const int w = settings.width, h = settings.height;
  size_t backdrop = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Any of the pixel's film positions could see the object if one of 5×5 probes over the pixel does.
      bool object = false;
      for (int j = 0; j <= 4 && !object; ++j)
        for (int i = 0; i <= 4 && !object; ++i) {
          Hit hit;
          object = stage().bvh.intersect(cameraRay(camera, w, h, Vec2(x + i / 4.0, y + j / 4.0)), hit) && scenes[0].isObject(hit.mesh);
        }
      if (object) continue;
      ++backdrop;
      for (size_t p = 1; p < scenes.size(); ++p)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(images[p].at(x, y)[c], images[0].at(x, y)[c]) << "pixel " << x << "," << y;
    }
  EXPECT_GT(backdrop, size_t(w * h / 2));
}

}  // namespace glossy::test

namespace glossy::test {

// SheetSettings is a RenderSettings: what a render is told (the reference tracer, cosine sampling, the
// roulette's depth) reaches every panel of a sheet rather than being dropped on the way.
TEST(CoherentPanels, ASheetRendersWithItsRenderSettings) {
  const MaterialFile chrome = loadMaterialFile(materialsDir() / "chrome.toml");
  const auto sheetWith = [&](auto&& set) {
    SheetSettings s;
    s.width = s.height = 24;
    s.spp = 4;
    s.threads = 2;
    s.progress = false;
    set(s);
    return renderSheet(stage().sheet, chrome, nullptr, "", s);
  };
  const Sheet plain = sheetWith([](SheetSettings&) {});
  const Sheet reference = sheetWith([](SheetSettings& s) { s.reference = true; });
  const Sheet cosine = sheetWith([](SheetSettings& s) { s.cosineBrdfSampling = true; });
  const Sheet roulette = sheetWith([](SheetSettings& s) { s.rouletteDepth = 1; });
  ASSERT_EQ(plain.panels.size(), cosine.panels.size());
  ASSERT_EQ(plain.panels.size(), reference.panels.size());
  bool referenceDiffers = false, cosineDiffers = false, rouletteDiffers = false;
  for (size_t k = 0; k < plain.panels.size(); ++k) {
    referenceDiffers |= reference.panels[k].image.pixels != plain.panels[k].image.pixels;
    cosineDiffers |= cosine.panels[k].image.pixels != plain.panels[k].image.pixels;
    rouletteDiffers |= roulette.panels[k].image.pixels != plain.panels[k].image.pixels;
  }
  EXPECT_TRUE(referenceDiffers);
  EXPECT_TRUE(cosineDiffers);
  EXPECT_TRUE(rouletteDiffers);
}

}  // namespace glossy::test
