// The parameter-file loader: every kind of bad value is an error naming the file, the fit and the key;
// good files round-trip through the writer; every committed library file loads.
#include "materials/core/input_error.h"
#include "materials/params/material_file.h"
#include "tests/support/test_support.h"

namespace glossy::test {

namespace {

const char* kGood = R"(name = "test-material"
measured = "test-material.binary"
source = "hand-written"

[[fit]]
model = "cook-torrance"
metric = "E1"
kd = [0.1, 0.2, 0.3]
ks = [0.05, 0.04, 0.03]
m = 0.1
eta = 1.5

[[fit]]
model = "smooth"
metric = "E2"
kd = [0, 0, 0]
a = [10, 20, 30]
b = 1000
c = 0.5
eta = 2.0
fresnel = "vh"
)";

struct BadCase {
  const char* what;
  const char* from;  // text in kGood to replace
  const char* to;
  std::vector<const char*> mentions;  // all must appear in the one-line message
};

std::string replaceOnce(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  if (at == std::string::npos) throw std::logic_error("test case text not found: " + from);
  return s.replace(at, from.size(), to);
}

}  // namespace

TEST(MaterialFile, GoodFileLoadsAndRoundTrips) {
  const MaterialFile m = parseMaterialToml(kGood, "good.toml");
  EXPECT_EQ(m.name, "test-material");
  EXPECT_EQ(m.measured, "test-material.binary");
  ASSERT_EQ(m.fits.size(), 2u);
  EXPECT_EQ(m.fits[0].id.str(), "smooth:E2");  // kept in the comparison grid's order
  EXPECT_EQ(m.fits[1].id.str(), "cook-torrance:E1");
  EXPECT_EQ(m.fits[1].params.scalar("m"), 0.1);
  const MaterialFile again = parseMaterialToml(toToml(m), "again.toml");
  EXPECT_EQ(again.name, m.name);
  EXPECT_EQ(again.measured, m.measured);
  EXPECT_EQ(again.source, m.source);
  EXPECT_EQ(again.fits, m.fits);
  const Brdf smooth = makeBrdf(m.fits[0]);
  ASSERT_NE(smooth.as<Smooth>(), nullptr);
  EXPECT_TRUE(smooth.as<Smooth>()->fresnelVH);
}

class BadMaterialFile : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadMaterialFile, IsAnErrorNamingFileFitAndKey) {
  const BadCase& c = GetParam();
  TempDir tmp;
  writeText(tmp / "broken.toml", replaceOnce(kGood, c.from, c.to));
  try {
    loadMaterialFile(tmp / "broken.toml");
    FAIL() << c.what << ": loaded without error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find("broken.toml"), std::string::npos) << msg;
    for (const char* m : c.mentions) EXPECT_NE(msg.find(m), std::string::npos) << c.what << ": '" << m << "' not in: " << msg;
  }
}

INSTANTIATE_TEST_SUITE_P(
    EachKindOfBadValue, BadMaterialFile,
    ::testing::Values(
        BadCase{"negative kd", "kd = [0.1, 0.2, 0.3]", "kd = [0.1, -0.2, 0.3]", {"fit 1 (cook-torrance:E1)", "'kd' (G)", "must be in [0, 1000000]"}},
        BadCase{"negative ks", "ks = [0.05, 0.04, 0.03]", "ks = [-0.05, 0.04, 0.03]", {"fit 1 (cook-torrance:E1)", "'ks' (R)", "must be in [0, 1000000]"}},
        BadCase{"negative a", "a = [10, 20, 30]", "a = [10, 20, -30]", {"fit 2 (smooth:E2)", "'a' (B)"}},
        BadCase{"negative b", "b = 1000", "b = -1000", {"fit 2 (smooth:E2)", "'b'", "must be in [0, 1000000000]"}},
        BadCase{"zero m", "m = 0.1", "m = 0.0", {"broken.toml:10: fit 1 (cook-torrance:E1): key 'm'", "must be in [0.0001, 10]"}},
        BadCase{"negative m", "m = 0.1", "m = -0.1", {"'m'", "must be in [0.0001, 10]"}},
        BadCase{"c zero", "c = 0.5", "c = 0", {"fit 2 (smooth:E2)", "'c'", "must be in [0.001, 100]"}},
        BadCase{"eta equal 1", "eta = 1.5", "eta = 1.0", {"fit 1 (cook-torrance:E1)", "'eta'", "must be in [1.000001, 1000]"}},
        BadCase{"eta below 1", "eta = 2.0", "eta = 0.7", {"fit 2 (smooth:E2)", "'eta'", "must be in [1.000001, 1000]"}},
        BadCase{"nan", "m = 0.1", "m = nan", {"'m'", "finite"}},
        BadCase{"inf", "b = 1000", "b = inf", {"'b'", "finite"}},
        BadCase{"-inf in rgb", "kd = [0.1, 0.2, 0.3]", "kd = [0.1, 0.2, -inf]", {"'kd' (B)", "finite"}},
        BadCase{"missing key", "m = 0.1\n", "", {"fit 1 (cook-torrance:E1)", "missing key 'm'"}},
        BadCase{"missing model", "model = \"cook-torrance\"\n", "", {"fit 1", "missing key 'model'"}},
        BadCase{"missing metric", "metric = \"E1\"\n", "", {"fit 1", "missing key 'metric'"}},
        BadCase{"unknown fit key", "m = 0.1", "m = 0.1\nroughness = 0.2", {"fit 1 (cook-torrance:E1)", "'roughness'", "unknown key"}},
        BadCase{"key of another model", "c = 0.5", "c = 0.5\nks = [1, 1, 1]", {"fit 2 (smooth:E2)", "'ks'", "unknown key"}},
        BadCase{"unknown top-level key", "source = \"hand-written\"", "colour = \"red\"", {"'colour'", "unknown key"}},
        BadCase{"unknown model", "model = \"cook-torrance\"", "model = \"phong\"", {"fit 1", "'model'", "unknown model 'phong'"}},
        BadCase{"bad metric", "metric = \"E1\"", "metric = \"E3\"", {"fit 1", "'metric'", "E1, E2, Ngan05 or Bagher12"}},
        BadCase{"two-channel rgb", "kd = [0.1, 0.2, 0.3]", "kd = [0.1, 0.2]", {"'kd'", "3 numbers"}},
        BadCase{"string for number", "m = 0.1", "m = \"0.1\"", {"'m'", "a number"}},
        BadCase{"scalar for rgb", "ks = [0.05, 0.04, 0.03]", "ks = 0.05", {"'ks'", "3 numbers"}},
        BadCase{"bad fresnel choice", "fresnel = \"vh\"", "fresnel = \"schlick\"", {"fit 2 (smooth:E2)", "'fresnel'", "projected, vh"}},
        BadCase{"duplicate fit", "[[fit]]\nmodel = \"smooth\"",
                "[[fit]]\nmodel = \"cook-torrance\"\nmetric = \"E1\"\nkd = [0, 0, 0]\nks = [0, 0, 0]\nm = 0.2\neta = 1.3\n\n"
                "[[fit]]\nmodel = \"smooth\"",
                {"fit 2 (cook-torrance:E1)", "second cook-torrance:E1"}},
        BadCase{"missing name", "name = \"test-material\"\n", "", {"missing key 'name'"}},
        BadCase{"syntax error", "m = 0.1", "m = = 0.1", {"TOML syntax error", ":10:"}}),
    [](const auto& info) {
      std::string s = info.param.what;
      for (char& c : s)
        if (!isalnum(static_cast<unsigned char>(c))) c = '_';
      return s;
    });

TEST(MaterialFile, MissingFileIsAnErrorNamingIt) {
  try {
    loadMaterialFile("/nonexistent/nowhere.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/nowhere.toml"), std::string::npos);
  }
}

TEST(MaterialFile, FitIdsParseAndRejectUnknowns) {
  EXPECT_EQ(FitId::parse("microfacet:E2", "--fit").str(), "microfacet:E2");
  EXPECT_THROW(FitId::parse("microfacet", "--fit"), InputError);
  EXPECT_THROW(FitId::parse("blinn:E1", "--fit"), InputError);
  EXPECT_THROW(FitId::parse("smooth:E9", "--fit"), InputError);
}

// glossy's own fit of a model and metric stands beside the published one under its own name,
// MODEL:METRIC:glossy, with what it was fitted to; MODEL:METRIC names the published fit, and glossy's only
// where the file has no published one.
TEST(MaterialFile, GlossysFitStandsBesideThePublishedOneUnderItsOwnName) {
  const std::string glossys = std::string(kGood) +
                              "\n[[fit]]\nmodel = \"cook-torrance\"\nmetric = \"E1\"\nby = \"glossy\"\nkd = [0.2, 0.2, 0.2]\n"
                              "ks = [0.05, 0.04, 0.03]\nm = 0.3\neta = 1.5\nerror = 0.01\ndata = \"test-material.binary.xz\"\n"
                              "database = \"MERL (NBRDF reconstruction)\"\ndate = \"2026-12-01\"\nsettings = \"grid\"\n";
  const MaterialFile m = parseMaterialToml(glossys, "both.toml");
  ASSERT_EQ(m.fits.size(), 3u);
  EXPECT_EQ(m.find(FitId::parse("cook-torrance:E1", "test"))->params.scalar("m"), 0.1) << "MODEL:METRIC is the paper's";
  const Fit* mine = m.find(FitId::parse("cook-torrance:E1:glossy", "test"));
  ASSERT_NE(mine, nullptr);
  EXPECT_EQ(mine->params.scalar("m"), 0.3);
  EXPECT_EQ(mine->data, "test-material.binary.xz");
  EXPECT_EQ(mine->database, "MERL (NBRDF reconstruction)");
  EXPECT_EQ(mine->date, "2026-12-01");
  EXPECT_EQ(m.fits[2].id.str(), "cook-torrance:E1:glossy") << "right after the published fit";
  EXPECT_EQ(parseMaterialToml(toToml(m), "again.toml").fits, m.fits);
  EXPECT_EQ(m.find(FitId::parse("smooth:E2:glossy", "test")), nullptr) << "glossy's names glossy's only";

  MaterialFile onlyGlossys = m;
  std::erase_if(onlyGlossys.fits, [](const Fit& f) { return f.id.str() == "cook-torrance:E1"; });
  ASSERT_NE(onlyGlossys.find(FitId::parse("cook-torrance:E1", "test")), nullptr);
  EXPECT_TRUE(onlyGlossys.find(FitId::parse("cook-torrance:E1", "test"))->id.isGlossys()) << "glossy's where none is published";
  EXPECT_EQ(onlyGlossys.findExact(FitId::parse("cook-torrance:E1", "test")), nullptr);

  EXPECT_THROW(FitId::parse("cook-torrance:E1:mine", "--fit"), InputError);
  EXPECT_THROW(FitId::parse("cook-torrance:E1:", "--fit"), InputError);
  EXPECT_THROW(parseMaterialToml(replaceOnce(glossys, "by = \"glossy\"", "by = \"Low\""), "bad.toml"), InputError);
}

// A file written by an earlier glossy fit has no 'by'; its fits carry settings, which only glossy fit
// writes, and so load as glossy's, not as the paper's.
TEST(MaterialFile, AnEarlierGlossyFitWithoutByLoadsAsGlossys) {
  const MaterialFile m = parseMaterialToml(replaceOnce(kGood, "eta = 1.5\n", "eta = 1.5\nsource = \"glossy fit to x.binary\"\nsettings = \"grid\"\n"),
                                           "old.toml");
  ASSERT_EQ(m.fits.size(), 2u);
  EXPECT_EQ(m.fits[1].id.str(), "cook-torrance:E1:glossy");
  EXPECT_EQ(m.findExact(FitId::parse("cook-torrance:E1", "test")), nullptr);
}

TEST(MaterialFile, EveryCommittedLibraryFileLoadsWithTheSixPublishedFits) {
  // Ngan et al. 2005 fitted 86 of the 100: those carry one fit per bbm ngan_*.fit file in
  // materials/published-fits. Bagher et al. 2012 fitted all 100: one sgd:Bagher12 each.
  long nganModels = 0;
  for (const auto& e : std::filesystem::directory_iterator(sourceDir() / "materials/published-fits"))
    nganModels += e.path().extension() == ".fit" && e.path().filename().string().starts_with("ngan_");
  size_t files = 0, nganMaterials = 0;
  for (const auto& e : std::filesystem::directory_iterator(materialsDir())) {
    if (e.path().extension() != ".toml") continue;
    const MaterialFile m = loadMaterialFile(e.path());
    EXPECT_EQ(m.name + ".toml", e.path().filename().string());
    EXPECT_EQ(m.measured, m.name + ".binary");
    const auto published = [&](std::string_view metric) {
      return std::count_if(m.fits.begin(), m.fits.end(), [&](const Fit& f) {
        return !f.id.isGlossys() && (metric.empty() ? f.id.isLowMetric() : f.id.metric == metric);
      });
    };
    EXPECT_EQ(published(""), 6) << m.name;
    EXPECT_EQ(published(FitId::kBagher12), 1) << m.name;
    EXPECT_NE(m.findExact(FitId{"sgd", std::string(FitId::kBagher12)}), nullptr) << m.name;
    EXPECT_TRUE(published(FitId::kNgan05) == 0 || published(FitId::kNgan05) == nganModels) << m.name;
    nganMaterials += published(FitId::kNgan05) == nganModels;
    for (const char* id : {"microfacet:E2", "smooth:E2", "ashikhmin-shirley:E1", "ashikhmin-shirley:E2", "cook-torrance:E1", "cook-torrance:E2"})
      EXPECT_NE(m.findExact(FitId::parse(id, "test")), nullptr) << m.name << " lacks the published " << id;
    ++files;
  }
  EXPECT_EQ(files, 100u);
  EXPECT_EQ(nganMaterials, nganModels > 0 ? 86u : 100u);
}

TEST(MaterialFile, MeasuredResolvesAgainstMerlDirThenEnvironmentAndAcceptsXz) {
  TempDir a, b;
  writeText(a / "x.binary", "");
  writeText(b / "y.binary.xz", "");
  MaterialFile m;
  m.measured = "x.binary";
  EXPECT_EQ(resolveMeasured(m.measured, a.path()), a / "x.binary");
  m.measured = "y.binary";
  EXPECT_EQ(resolveMeasured(m.measured, a.path()), std::nullopt);
  setenv("GLOSSY_MERL_DIR", b.path().c_str(), 1);
  EXPECT_EQ(resolveMeasured(m.measured, a.path()), b / "y.binary.xz");
  unsetenv("GLOSSY_MERL_DIR");
  m.measured.clear();
  EXPECT_EQ(resolveMeasured(m.measured, a.path()), std::nullopt);
}

// After the tables (--merl-dir, $GLOSSY_MERL_DIR, the working folder) comes the network embedded beside
// the material file; a name from a file cannot lead out of the material's folder.
TEST(MaterialFile, MeasuredFallsBackToTheEmbeddedNetworkLast) {
  TempDir merl, materials, env;
  writeText(materials / "z.nbrdf", "");
  writeText(merl / "z.binary", "");
  writeText(env / "z.binary.xz", "");
  EXPECT_EQ(resolveMeasured("z.binary", merl.path(), materials.path()), merl / "z.binary");
  setenv("GLOSSY_MERL_DIR", env.path().c_str(), 1);
  EXPECT_EQ(resolveMeasured("z.binary", {}, materials.path()), env / "z.binary.xz");
  unsetenv("GLOSSY_MERL_DIR");
  EXPECT_EQ(resolveMeasured("z.binary", {}, materials.path()), materials / "z.nbrdf");
  EXPECT_EQ(resolveMeasured("z.binary.xz", {}, materials.path()), materials / "z.nbrdf");
  EXPECT_EQ(resolveMeasured("z.nbrdf", {}, materials.path()), materials / "z.nbrdf");
  EXPECT_EQ(resolveMeasured("z.binary", {}, {}), std::nullopt) << "no material folder: no network";
  EXPECT_EQ(resolveMeasured("../../z.binary", {}, materials.path()), materials / "z.nbrdf");
  EXPECT_EQ(resolveMeasured("..", {}, materials.path()), std::nullopt);
  EXPECT_EQ(resolveMeasured("w.binary", {}, materials.path()), std::nullopt);
}

}  // namespace glossy::test
