// A model registered at run time, as a plugin would add one: a header-only model struct and one
// registerModel call make it a name that material files accept, a Brdf, and a sheet panel; names nobody
// registered stay one-line input errors.
#include "materials/core/input_error.h"
#include "materials/fitting/fitter.h"
#include "materials/models/registry.h"
#include "renderer/sheet/sheet.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/test_support.h"

namespace glossy::test {

namespace {

// ρ = albedo / π with one grey parameter, under its own name: what a convex object shows under constant
// radiance is then known exactly.
struct ConstantAlbedo {
  static constexpr std::string_view kName = "test-constant-albedo";
  static constexpr std::string_view kLabel = "Constant albedo (test)";
  static constexpr std::string_view kShortLabel = "Const";
  static constexpr ParamSpec kParams[] = {
      {"albedo", ParamKind::Scalar, {0.0, 1.0}, "directional albedo"},
  };
  static ConstantAlbedo fromParams(const ParamSet& p) { return {p.scalar("albedo")}; }

  double albedo = 0.0;

  Rgb eval(const Vec3& L, const Vec3& V) const { return L.z > 0.0 && V.z > 0.0 ? Rgb(albedo * kInvPi) : Rgb(0.0); }
  BrdfSample sample(const Vec3& V, double /*uLobe*/, Vec2 u) const { return sampleCosineLobe(*this, V, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return V.z > 0.0 ? cosineHemispherePdf(L) : 0.0; }
};

// The registry is process-wide and GoogleTest may run these tests in one process.
void registerTestModel() {
  if (!findModel(ConstantAlbedo::kName)) registerModel(modelInfo<ConstantAlbedo>());
}

constexpr double kAlbedo = 0.6;
constexpr const char* kMaterial = R"(name = "plugin-grey"

[[fit]]
model = "test-constant-albedo"
metric = "E2"
albedo = 0.6
)";

}  // namespace

TEST(ModelRegistry, ARegisteredModelIsAModelEverywhere) {
  registerTestModel();
  EXPECT_EQ(analyticModels().back().name, ConstantAlbedo::kName) << "after the built-in models";
  EXPECT_NE(knownModelNames().find("test-constant-albedo"), std::string::npos);
  EXPECT_THROW(registerModel(modelInfo<ConstantAlbedo>()), std::logic_error) << "a name already taken";
  // Not fittable: the fitter needs a model's static type.
  EXPECT_NE(expectInputError([] { requireFittable(ConstantAlbedo::kName); }).find("cannot fit"), std::string::npos);

  const MaterialFile m = parseMaterialToml(kMaterial, "plugin-grey.toml");
  ASSERT_EQ(m.fits.size(), 1u);
  EXPECT_EQ(parseMaterialToml(toToml(m), "again.toml").fits, m.fits) << "written and read back";
  const Brdf brdf = makeBrdf(*m.find(FitId::parse("test-constant-albedo:E2", "--fit")));
  ASSERT_NE(brdf.as<ConstantAlbedo>(), nullptr);
  EXPECT_EQ(brdf.as<Lambertian>(), nullptr);
  EXPECT_DOUBLE_EQ(eval(brdf, Vec3(0.6, 0.0, 0.8), Vec3(0.0, 0.0, 1.0)).g, kAlbedo * kInvPi);
  const std::string bad = expectInputError([] { parseMaterialToml(R"(name = "x"
[[fit]]
model = "test-constant-albedo"
metric = "E1"
albedo = -1.0
)", "x.toml"); });
  EXPECT_NE(bad.find("key 'albedo'"), std::string::npos) << bad;
}

TEST(ModelRegistry, ASheetPanelRendersARegisteredModel) {
  registerTestModel();
  const MaterialFile m = parseMaterialToml(kMaterial, "plugin-grey.toml");
  // A sphere filling the whole view under radiance 1: a convex object returns albedo × 1 from every
  // point, after exactly one reflection.
  SceneDescription description;
  description.materials.emplace_back().name = "object";
  description.meshes.push_back(uvSphere(1.0, 128, 64, 0));
  const EmbreeScene bvh(description);
  const Environment environment = Environment::constant(Rgb(1.0));
  const Camera camera = orthographicDown(0.6, {0, 0, 5}, {0, 0, 0}, {0, 1, 0});
  SheetSettings settings;
  settings.width = settings.height = 32;
  settings.spp = 16;
  settings.progress = false;
  settings.panels = {SheetPanel::ofFit({"test-constant-albedo", "E2"})};

  const Sheet sheet = renderSheet(makeSheetScene(description, bvh, environment, camera), m, nullptr,
                                  "no measured table", settings);
  ASSERT_EQ(sheet.panels.size(), 1u);
  const PanelRender& p = sheet.panels[0];
  ASSERT_FALSE(p.empty) << p.note;
  EXPECT_EQ(p.panel.layer, "test_constant_albedo_E2");
  EXPECT_EQ(p.panel.label, "Const E2");
  EXPECT_FALSE(sheet.hasMeasured());
  EXPECT_FALSE(p.figures.compared) << "no measured panel to compare with";
  EXPECT_EQ(sheet.grid.width, 32);
  double sum = 0.0;
  size_t object = 0;
  for (size_t i = 0; i < sheet.objectMask.size(); ++i) {
    if (!sheet.objectMask[i]) continue;
    ++object;
    for (int c = 0; c < 3; ++c) sum += p.image.pixels[3 * i + c];
  }
  ASSERT_EQ(object, sheet.objectMask.size()) << "the sphere fills the view";
  // 16384 samples, each within a few times the albedo: the mean's noise is well under 0.5 %.
  EXPECT_NEAR(sum / (3.0 * double(object)), kAlbedo, 0.01 * kAlbedo);
}

TEST(ModelRegistry, AnUnknownModelIsStillAOneLineInputError) {
  registerTestModel();
  const std::string inFile = expectInputError([] { parseMaterialToml(R"(name = "x"
[[fit]]
model = "no-such-model"
metric = "E2"
)", "x.toml"); });
  EXPECT_NE(inFile.find("x.toml"), std::string::npos) << inFile;
  EXPECT_NE(inFile.find("unknown model 'no-such-model'"), std::string::npos) << inFile;
  EXPECT_NE(inFile.find("test-constant-albedo"), std::string::npos) << "the known models include the registered one: " << inFile;
  const std::string onCommandLine = expectInputError([] { FitId::parse("no-such-model:E2", "--fit"); });
  EXPECT_NE(onCommandLine.find("--fit: unknown model 'no-such-model'"), std::string::npos) << onCommandLine;
}

}  // namespace glossy::test
