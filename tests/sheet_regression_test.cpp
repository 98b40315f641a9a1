// Image regression of the material sheets: the six supplement materials re-rendered at 2 × 512 spp against
// the 2048-spp references in tests/reference/ (made by scripts/make-reference-sheets), panel by panel, with
// a tolerance derived from both renders' noise (tests/support/image_regression.h); family-wise
// significance 0.01 (Šidák) over all panels. A model made 2 % brighter must fail.
#include "renderer/sheet/sheet.h"
#include "tests/support/chi2.h"
#include "tests/support/image_regression.h"
#include "tests/support/test_support.h"

#include <memory>

namespace glossy::test {

namespace {

// Halves of a quarter of the reference's samples: some panels' noise is heavy-tailed (chrome's
// Ashikhmin-Shirley E1: caustics through a near-mirror), and halves of a sixteenth miss the rare bright
// paths the reference catches often enough to fail the block test, unbiased as they are.
constexpr int kSize = 64, kReferenceSpp = 2048, kHalfSpp = 512;

double alpha() { return sidakAlpha(0.01, int(supplementMaterials().size() * sheetPanels().size())); }

// The reference's setting: the preview scene, its camera, the built-in sky, the default depth.
struct Stage {
  SceneDescription description = loadGltf(sourceDir() / "scenes/preview.gltf");
  EmbreeScene bvh{description};
  Environment environment = Environment::makeDefault();
  SheetScene scene = makeSheetScene(description, bvh, environment, description.cameras.front());
};
const Stage& stage() {
  static const Stage s;
  return s;
}

Sheet renderHalf(const MaterialFile& m, std::shared_ptr<const MerlTable> measured, uint32_t seed) {
  SheetSettings s;
  s.width = s.height = kSize;
  s.spp = kHalfSpp;
  s.seed = seed;
  s.progress = false;
  return renderSheet(stage().scene, m, std::move(measured), "", s);
}

std::filesystem::path referencePath(const std::string& name) { return sourceDir() / "tests/reference" / (name + ".exr"); }

RgbImage referencePanel(const std::string& name, size_t k) {
  return crop(readImageLayer(referencePath(name), sheetPanels()[k].layer), int(k) * kSize, 0, kSize, kSize);
}

ImageComparison comparePanel(const Sheet& a, const Sheet& b, const std::string& name, size_t k) {
  return compareWithReference(a.panels[k].image, b.panels[k].image, kHalfSpp, referencePanel(name, k), kReferenceSpp,
                              a.objectMask, alpha());
}

class SheetRegression : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST(SheetReference, IsTheSettingTheTestsAssume) {
  for (const std::string& name : supplementMaterials()) {
    ASSERT_TRUE(std::filesystem::exists(referencePath(name))) << "run scripts/make-reference-sheets";
    EXPECT_EQ(readImageAttribute(referencePath(name), "glossy:spp"), std::to_string(kReferenceSpp)) << name;
    EXPECT_EQ(readImageAttribute(referencePath(name), "glossy:panelSize"), "64x64") << name;
    EXPECT_EQ(readImageAttribute(referencePath(name), "glossy:env"), "default sky") << name;
    EXPECT_NE(readImageAttribute(referencePath(name), "glossy:scene").find("scenes/preview.gltf"), std::string::npos) << name;
  }
}

TEST_P(SheetRegression, AnalyticPanelsMatchTheReference) {
  const std::string name = GetParam();
  const MaterialFile m = loadMaterialFile(materialsDir() / (name + ".toml"));
  const Sheet a = renderHalf(m, nullptr, 1), b = renderHalf(m, nullptr, 2);
  for (size_t k = 1; k < sheetPanels().size(); ++k) {
    const ImageComparison c = comparePanel(a, b, name, k);
    RecordProperty(sheetPanels()[k].layer + "_bias", std::to_string(c.relativeBias));
    RecordProperty(sheetPanels()[k].layer + "_p", std::to_string(std::min(c.meanP, c.blockP)));
    EXPECT_TRUE(c.passed) << name << " " << sheetPanels()[k].label << ": " << c.message;
  }
}

TEST_P(SheetRegression, MeasuredPanelMatchesTheReference) {
  const std::string name = GetParam();
  GLOSSY_REQUIRE_SHARED("merl/" + name + ".binary.xz");
  MaterialFile m = loadMaterialFile(materialsDir() / (name + ".toml"));
  m.fits.clear();  // only the measured panel is rendered
  const auto table = std::make_shared<const MerlTable>(MerlTable::load(sharedDir() / "merl" / (name + ".binary")));
  const Sheet a = renderHalf(m, table, 1), b = renderHalf(m, table, 2);
  const ImageComparison c = comparePanel(a, b, name, 0);
  RecordProperty("measured_bias", std::to_string(c.relativeBias));
  RecordProperty("measured_p", std::to_string(std::min(c.meanP, c.blockP)));
  EXPECT_TRUE(c.passed) << name << " Measured: " << c.message;
}

INSTANTIATE_TEST_SUITE_P(Supplement, SheetRegression, ::testing::ValuesIn(supplementMaterials()),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& c : s)
                             if (c == '-') c = '_';
                           return s;
                         });

TEST(SheetRegressionPower, AModelTwoPercentBrighterFails) {
  // Every fit of alum-bronze with Kd and A/Ks × 1.02: ρ × 1.02 exactly.
  MaterialFile m = loadMaterialFile(materialsDir() / "alum-bronze.toml");
  for (Fit& f : m.fits)
    for (const char* key : {"kd", "a", "ks"})
      if (f.params.has(key)) f.params.set(key, f.params.rgb(key) * 1.02);
  const Sheet a = renderHalf(m, nullptr, 1), b = renderHalf(m, nullptr, 2);
  for (size_t k = 1; k < sheetPanels().size(); ++k) {
    const ImageComparison c = comparePanel(a, b, "alum-bronze", k);
    EXPECT_FALSE(c.passed) << sheetPanels()[k].label << " 2 % brighter passed: " << c.message;
    RecordProperty(sheetPanels()[k].layer + "_meanZ", std::to_string(c.meanZ));
    RecordProperty(sheetPanels()[k].layer + "_perturbedBias", std::to_string(c.relativeBias));
  }
}

}  // namespace glossy::test
