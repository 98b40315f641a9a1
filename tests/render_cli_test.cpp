// glossy render through the command line: the EXR and its metadata, determinism, and bad input.
#include "renderer/image/exr_image.h"
#include "tests/support/test_support.h"

#include <cmath>

namespace glossy::test {

namespace {

std::vector<std::string> small(const TempDir& tmp, const std::string& name, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", "--scene", (sourceDir() / "scenes/sphere.gltf").string(), "--width", "24",
                                   "--height", "24", "--spp", "4", "-o", (tmp / name).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

}  // namespace

TEST(CliRender, WritesAnExrWithTheContractsMetadata) {
  TempDir tmp;
  const RunResult r = runGlossy(small(tmp, "a.exr", {"--material", (materialsDir() / "chrome.toml").string(), "--fit", "smooth:E2", "--seed", "3"}));
  ASSERT_EQ(r.status, 0) << r.err;
  const RgbImage img = readRgbImage(tmp / "a.exr");
  EXPECT_EQ(img.width, 24);
  for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v));
  const auto attr = [&](const char* name) { return readImageAttribute(tmp / "a.exr", name); };
  EXPECT_NE(attr("glossy:material").find("chrome.toml"), std::string::npos);
  EXPECT_EQ(attr("glossy:fit"), "smooth:E2");
  EXPECT_EQ(attr("glossy:spp"), "4");
  EXPECT_EQ(attr("glossy:seed"), "3");
  EXPECT_NE(attr("glossy:scene").find("sphere.gltf"), std::string::npos);
  EXPECT_EQ(attr("glossy:env"), "default sky");
  EXPECT_EQ(attr("glossy:smoothFresnel"), "projected");
  EXPECT_FALSE(attr("glossy:renderSeconds").empty());
  EXPECT_FALSE(attr("glossy:version").empty());
  EXPECT_FALSE(attr("glossy:conventions").empty());
  EXPECT_EQ(attr("glossy:droppedSamples"), "0");
  for (const auto& e : std::filesystem::directory_iterator(tmp.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "temporary left behind";
}

TEST(CliRender, SameSeedRendersIdenticallyTwice) {
  TempDir tmp;
  ASSERT_EQ(runGlossy(small(tmp, "a.exr", {"--seed", "7"})).status, 0);
  ASSERT_EQ(runGlossy(small(tmp, "b.exr", {"--seed", "7", "--threads", "1"})).status, 0);
  ASSERT_EQ(runGlossy(small(tmp, "c.exr", {"--seed", "8"})).status, 0);
  EXPECT_EQ(readRgbImage(tmp / "a.exr").pixels, readRgbImage(tmp / "b.exr").pixels);
  EXPECT_NE(readRgbImage(tmp / "a.exr").pixels, readRgbImage(tmp / "c.exr").pixels);
}

TEST(CliRender, BadInputExitsTwoWithOneLineAndWritesNothing) {
  TempDir tmp;
  writeText(tmp / "broken.gltf", "{ not json");
  expectOneLineError(runGlossy({"render", "--scene", (tmp / "broken.gltf").string(), "-o", (tmp / "x.exr").string()}), "broken.gltf");
  expectOneLineError(runGlossy(small(tmp, "x.exr", {"--env", (tmp / "absent.hdr").string()})), "absent.hdr");
  expectOneLineError(runGlossy(small(tmp, "x.exr", {"--env-constant", "1,x,3"})), "--env-constant");
  expectOneLineError(runGlossy(small(tmp, "x.exr", {"--env-constant", "-1"})), "--env-constant");
  expectOneLineError(runGlossy(small(tmp, "x.exr", {"--camera", "nope"})), "no camera named 'nope'");
  expectOneLineError(runGlossy(small(tmp, "x.exr", {"--measured", (tmp / "absent.binary").string()})), "absent.binary");
  expectOneLineError(runGlossy(small(tmp, "x.exr", {"--material", (materialsDir() / "chrome.toml").string(), "--fit", "lambertian:E1"})),
                     "has no lambertian:E1 fit");
  EXPECT_EQ(runGlossy(small(tmp, "x.exr", {"--spp", "0"})).status, 2);
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.exr"));
}

TEST(CliRender, OrthographicCameraAndConstantEnvironmentByName) {
  TempDir tmp;
  const RunResult r = runGlossy(small(tmp, "o.exr", {"--camera", "ortho", "--env-constant", "1", "--material",
                                                     (materialsDir() / "gold-paint.toml").string(), "--fit", "cook-torrance:E2"}));
  ASSERT_EQ(r.status, 0) << r.err;
  const RgbImage img = readRgbImage(tmp / "o.exr");
  EXPECT_FLOAT_EQ(img.at(0, 0)[0], 1.0f) << "the corner sees the constant environment";
  EXPECT_LT(img.at(12, 12)[0], 0.5f) << "the centre sees the sphere";
  EXPECT_EQ(readImageAttribute(tmp / "o.exr", "glossy:env"), "constant 1,1,1");
}

TEST(CliRender, MetadataNamesTheSceneBoundFitAndSeedsBeyondInt) {
  TempDir tmp;
  // The preview scene binds one fit (extras.glossy): glossy:fit names it, not just "per scene binding".
  const RunResult r = runGlossy({"render", "--width", "16", "--height", "16", "--spp", "1", "--seed", "4294967295",
                                 "-o", (tmp / "p.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readImageAttribute(tmp / "p.exr", "glossy:fit"), "microfacet:E2");
  EXPECT_EQ(readImageAttribute(tmp / "p.exr", "glossy:seed"), "4294967295");
}

TEST(CliRender, MeasuredTablesReportTheirUnmeasuredBins) {
  TempDir tmp;
  // A table whose first θ_h row is unmeasured: 90 × 180 = 16200 bins.
  writeText(tmp / "holes.binary", syntheticMerlBytes([](int h, int, int) { return h == 0 ? Rgb(-1.0) : Rgb(300.0); }));
  const RunResult r = runGlossy(small(tmp, "m.exr", {"--measured", (tmp / "holes.binary").string()}));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readImageAttribute(tmp / "m.exr", "glossy:measuredInvalidBins"), "16200");
  EXPECT_NE(r.err.find("16200 of 1458000 bins unmeasured"), std::string::npos) << r.err;
  const RunResult e = runGlossy({"eval", "--measured", (tmp / "holes.binary").string()}, "0.3,0,0.954,-0.3,0,0.954\n");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_NE(e.err.find("holes.binary: 16200 of 1458000 bins unmeasured"), std::string::npos) << e.err;
}

TEST(CliRender, AnEmissionThatOverflowsIsBadInput) {
  TempDir tmp;
  writeText(tmp / "hot.gltf", R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_emissive_strength"],
    "materials": [{"name": "hot", "emissiveFactor": [1e300, 1, 1],
                   "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e300}}}],
    "meshes": [], "nodes": [], "scenes": [{"nodes": []}], "scene": 0})");
  expectOneLineError(runGlossy({"render", "--scene", (tmp / "hot.gltf").string(), "-o", (tmp / "x.exr").string()}),
                     "overflows");
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.exr"));
}

}  // namespace glossy::test
