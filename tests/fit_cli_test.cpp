// glossy fit and glossy error through the command line (shared/spec/interfaces.md), on MERL-format
// tables the tests write; and the published fits against shared/merl's tables.
#include "materials/fitting/metric.h"
#include "materials/params/material_file.h"
#include "renderer/image/exr_image.h"
#include "tests/support/test_support.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <regex>

namespace glossy::test {

namespace {

const Brdf kTruth = CookTorrance{Rgb(0.1, 0.08, 0.05), Rgb(0.4, 0.3, 0.25), 0.08, 1.7};

std::filesystem::path writeTable(const TempDir& dir, const std::string& name, const Brdf& brdf,
                                 const BinPredicate& unmeasured = {}) {
  const std::filesystem::path path = dir / (name + ".binary");
  writeText(path, tabulatedMerlBytes(brdf, unmeasured));
  return path;
}

// A copy of a library file with its published fits only (the library's hold glossy's refits too), so that a
// fit into it is added, not a replacement of glossy's earlier one.
void copyPublishedFits(const std::string& name, const std::filesystem::path& to) {
  MaterialFile library = loadMaterialFile(materialsDir() / (name + ".toml"));
  std::erase_if(library.fits, [](const Fit& f) { return f.id.isGlossys(); });
  writeText(to, toToml(library));
}

}  // namespace

TEST(CliFit, UpdatesTheMaterialFileKeepingItsOtherFitsAndRecordsTheErrorAndSettings) {
  TempDir dir;
  const auto table = writeTable(dir, "synthetic-ct", kTruth);
  const auto toml = dir / "synthetic-ct.toml";
  writeText(toml, "name = \"synthetic-ct\"\nmeasured = \"synthetic-ct.binary\"\n\n[[fit]]\nmodel = \"ashikhmin-shirley\"\n"
                  "metric = \"E2\"\nkd = [0.1, 0.1, 0.1]\nks = [0.2, 0.2, 0.2]\nn = 100.0\neta = 1.5\n");
  const RunResult r = runGlossy({"fit", "--measured", table.string(), "--model", "cook-torrance", "--metric", "E1", "-o", toml.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("cook-torrance:E1:glossy: E1 = "), std::string::npos) << r.err;

  const MaterialFile m = loadMaterialFile(toml);
  ASSERT_EQ(m.fits.size(), 2u);
  ASSERT_NE(m.find({"ashikhmin-shirley", "E2"}), nullptr);
  const Fit* fit = m.find({"cook-torrance", "E1"});
  ASSERT_NE(fit, nullptr);
  ASSERT_TRUE(fit->error.has_value());
  EXPECT_NE(fit->settings.find("θo 15"), std::string::npos) << fit->settings;
  EXPECT_NEAR(fit->params.scalar("m"), 0.08, 0.08 * 0.03);

  // glossy error reports the same E for it, and E2 beside it, in the table and as JSON.
  const RunResult e = runGlossy({"error", "--measured", table.string(), "--material", toml.string(), "--json"});
  ASSERT_EQ(e.status, 0) << e.err;
  const auto json = nlohmann::json::parse(e.out);
  ASSERT_EQ(json["fits"].size(), 2u);
  bool seen = false;
  for (const auto& f : json["fits"]) {
    if (f["fit"] != "cook-torrance:E1:glossy") continue;
    seen = true;
    EXPECT_NEAR(f["E1"].get<double>(), *fit->error, 1e-12);
    EXPECT_NEAR(f["stored"].get<double>(), *fit->error, 0.0);
    EXPECT_GT(f["E2"].get<double>(), 0.0);
  }
  EXPECT_TRUE(seen) << e.out;
  EXPECT_EQ(json["validPairs"].get<size_t>(), MetricGrid::kPairs);

  const RunResult t = runGlossy({"error", "--measured", table.string(), "--material", toml.string()});
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("cook-torrance:E1:glossy"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("ashikhmin-shirley:E2"), std::string::npos) << t.out;
}

// The README's own example: fitting into the library's file adds glossy's fit beside the paper's, which
// stays as it was; a second fit replaces glossy's first and says so; only --replace removes the paper's. A
// sheet shows the paper's fit under the paper's label, and glossy's labelled as glossy's.
TEST(CliFit, AddsItsFitBesideThePublishedOneAndNeverReplacesItUnasked) {
  TempDir dir;
  const auto table = writeTable(dir, "alum-bronze", kTruth);
  const auto toml = dir / "alum-bronze.toml";
  copyPublishedFits("alum-bronze", toml);
  const MaterialFile published = loadMaterialFile(toml);
  const FitId ctE2 = FitId::parse("cook-torrance:E2", "test"), glossys = FitId::parse("cook-torrance:E2:glossy", "test");
  const std::vector<std::string> fit = {"fit", "--measured", table.string(), "--model", "cook-torrance", "--metric", "E2",
                                        "--starts", "1", "--max-iterations", "20", "-o", toml.string()};

  RunResult r = runGlossy(fit);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("the published cook-torrance:E2 fit stays beside it"), std::string::npos) << r.err;
  MaterialFile m = loadMaterialFile(toml);
  ASSERT_EQ(m.fits.size(), published.fits.size() + 1);
  EXPECT_EQ(*m.findExact(ctE2), *published.findExact(ctE2)) << "the paper's fit untouched";
  EXPECT_EQ(m.find(ctE2), m.findExact(ctE2)) << "MODEL:METRIC still names the paper's";
  const Fit* mine = m.findExact(glossys);
  ASSERT_NE(mine, nullptr);
  EXPECT_EQ(mine->data, "alum-bronze.binary");
  EXPECT_EQ(mine->database, "MERL");
  EXPECT_TRUE(std::regex_match(mine->date, std::regex(R"(\d{4}-\d{2}-\d{2})"))) << mine->date;
  ASSERT_TRUE(mine->error.has_value());
  EXPECT_NE(readText(toml).find("by = \"glossy\""), std::string::npos);

  r = runGlossy(fit);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("replaces glossy's earlier cook-torrance:E2:glossy fit (E2 = "), std::string::npos) << r.err;
  EXPECT_EQ(loadMaterialFile(toml).fits.size(), published.fits.size() + 1);

  // A sheet of the file: the paper's fit in its slot, under its label.
  const auto sheet = [&](const std::string& name) {
    const RunResult s = runGlossy({"sheet", "--material", toml.string(), "--width", "16", "--height", "16", "--spp", "4", "-o",
                                   (dir / (name + ".exr")).string()});
    EXPECT_EQ(s.status, 0) << s.err;
    return std::pair{readImageAttribute(dir / (name + ".exr"), "glossy:panel.cook_torrance_E2.label"),
                     readImageAttribute(dir / (name + ".exr"), "glossy:panel.cook_torrance_E2.fit")};
  };
  EXPECT_EQ(sheet("both"), std::pair(std::string("CT E2"), std::string("cook-torrance:E2")));

  r = runGlossy([&] { auto a = fit; a.push_back("--replace"); return a; }());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("removes the published cook-torrance:E2 fit (--replace)"), std::string::npos) << r.err;
  m = loadMaterialFile(toml);
  EXPECT_EQ(m.fits.size(), published.fits.size());
  EXPECT_EQ(m.findExact(ctE2), nullptr);
  ASSERT_NE(m.find(ctE2), nullptr);
  EXPECT_TRUE(m.find(ctE2)->id.isGlossys()) << "glossy's stays marked as glossy's";
  EXPECT_EQ(sheet("glossys"), std::pair(std::string("CT E2 (glossy fit)"), std::string("cook-torrance:E2:glossy")));
}

// A fit goes only into its own material's file: alum-bronze's table fitted into chrome.toml would store
// alum-bronze's fit as chrome's own (and replace chrome's). Refused before fitting, the file untouched,
// whether the file names its material by `measured` or, having none, by `name`.
TEST(CliFit, AFitOfOneMaterialIntoAnothersFileIsRefused) {
  TempDir dir;
  const auto table = writeTable(dir, "alum-bronze", kTruth);
  const auto chrome = dir / "chrome.toml";
  copyPublishedFits("chrome", chrome);
  writeText(dir / "nameonly.toml", "name = \"gold-paint\"\n\n[[fit]]\nmodel = \"lambertian\"\nmetric = \"E2\"\nkd = [0.1, 0.1, 0.1]\n");
  for (const auto& toml : {chrome, dir / "nameonly.toml"}) {
    SCOPED_TRACE(toml.string());
    const std::string before = readText(toml);
    const RunResult r = runGlossy({"fit", "--measured", table.string(), "--model", "cook-torrance", "--metric", "E2", "--starts", "1",
                                   "--max-iterations", "5", "-o", toml.string()});
    expectOneLineError(r, toml.string());
    expectOneLineError(r, "alum-bronze.binary");
    EXPECT_EQ(readText(toml), before);
  }
  // Its own file, under any file name, takes it.
  const auto mine = dir / "my-copy.toml";
  copyPublishedFits("alum-bronze", mine);
  EXPECT_EQ(runGlossy({"fit", "--measured", table.string(), "--model", "cook-torrance", "--metric", "E2", "--starts", "1",
                       "--max-iterations", "5", "-o", mine.string()}).status, 0);
}

TEST(CliFit, WithoutAnOutputFileWritesTheNewMaterialToStdout) {
  TempDir dir;
  const auto table = writeTable(dir, "plain", Lambertian{Rgb(0.3, 0.2, 0.1)});
  // --threads 0: all cores, as every --threads and glossy.fit take it.
  const RunResult r = runGlossy({"fit", "--measured", table.string(), "--model", "ashikhmin-shirley", "--metric", "E2", "--starts", "1",
                                 "--threads", "0"});
  ASSERT_EQ(r.status, 0) << r.err;
  const MaterialFile m = parseMaterialToml(r.out, "stdout");
  EXPECT_EQ(m.name, "plain");
  EXPECT_EQ(m.measured, "plain.binary");
  ASSERT_EQ(m.fits.size(), 1u);
  EXPECT_EQ(m.fits[0].id.str(), "ashikhmin-shirley:E2:glossy");
  const Rgb kd = m.fits[0].params.rgb("kd");
  EXPECT_NEAR(kd.r, 0.3, 0.01);
  EXPECT_NEAR(kd.b, 0.1, 0.01);
}

TEST(CliFit, BadDataIsAOneLineErrorAndWritesNothing) {
  TempDir dir;
  const auto empty = writeTable(dir, "empty", Lambertian{Rgb(0.5)}, [](int, int, int) { return true; });
  const RunResult r = runGlossy({"fit", "--measured", empty.string(), "--model", "cook-torrance", "--metric", "E2", "-o", (dir / "out.toml").string()});
  expectOneLineError(r, "empty.binary");
  EXPECT_NE(r.err.find("unmeasured"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.toml"));

  std::string bytes = tabulatedMerlBytes(Lambertian{Rgb(0.5)});
  const double nan = std::nan("");
  std::memcpy(bytes.data() + 12 + 8 * 777, &nan, sizeof nan);
  writeText(dir / "nan.binary", bytes);
  expectOneLineError(runGlossy({"fit", "--measured", (dir / "nan.binary").string(), "--model", "smooth", "--metric", "E1"}), "nan.binary");

  writeText(dir / "short.binary", bytes.substr(0, 1000));
  expectOneLineError(runGlossy({"fit", "--measured", (dir / "short.binary").string(), "--model", "smooth", "--metric", "E1"}), "short.binary");

  const auto good = writeTable(dir, "good", kTruth);
  expectOneLineError(runGlossy({"fit", "--measured", good.string(), "--model", "lambertian", "--metric", "E1"}), "cannot fit");
  expectOneLineError(runGlossy({"fit", "--measured", good.string(), "--model", "smooth", "--metric", "E3"}), "E3");
  writeText(dir / "broken.toml", "name = \"x\"\n[[fit]]\nmodel = \"smooth\"\n");
  expectOneLineError(runGlossy({"fit", "--measured", good.string(), "--model", "smooth", "--metric", "E1", "-o", (dir / "broken.toml").string()}),
                     "broken.toml");
  EXPECT_EQ(readText(dir / "broken.toml"), "name = \"x\"\n[[fit]]\nmodel = \"smooth\"\n");
}

TEST(CliFit, BatchFitsEveryTableAndResumes) {
  TempDir dir;
  std::filesystem::create_directories(dir / "tables");
  writeText(dir / "tables" / "one.binary", tabulatedMerlBytes(kTruth));
  writeText(dir / "tables" / "two.binary", tabulatedMerlBytes(AshikhminShirley{Rgb(0.2), Rgb(0.3), 200.0, 1.5}));
  const std::vector<std::string> args = {"fit", "--measured-dir", (dir / "tables").string(), "--out-dir", (dir / "fits").string(),
                                         "--model", "ashikhmin-shirley", "--metric", "E2", "--starts", "2"};
  const RunResult first = runGlossy(args);
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.err.find("[2/2] two ashikhmin-shirley:E2"), std::string::npos) << first.err;
  const MaterialFile two = loadMaterialFile(dir / "fits" / "two.toml");
  ASSERT_EQ(two.fits.size(), 1u);
  EXPECT_NEAR(two.fits[0].params.scalar("n"), 200.0, 200.0 * 0.03);
  const std::string before = readText(dir / "fits" / "one.toml");

  const RunResult again = runGlossy(args);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.err.find("2 fits, 2 already done"), std::string::npos) << again.err;
  EXPECT_EQ(again.err.find("[1/2]"), std::string::npos) << again.err;
  EXPECT_EQ(readText(dir / "fits" / "one.toml"), before);
}

// A batch into a folder that holds the library's file follows the same rule: glossy's fits beside the
// paper's, which stay; and it resumes past its own fits only, never taking the paper's for one of them.
TEST(CliFit, BatchAddsBesideThePublishedFitsAndResumesPastItsOwnOnly) {
  TempDir dir;
  std::filesystem::create_directories(dir / "tables");
  std::filesystem::create_directories(dir / "lib");
  writeText(dir / "tables" / "alum-bronze.binary", tabulatedMerlBytes(kTruth));
  copyPublishedFits("alum-bronze", dir / "lib" / "alum-bronze.toml");
  const std::string before = readText(dir / "lib" / "alum-bronze.toml");
  const std::vector<std::string> args = {"fit", "--measured-dir", (dir / "tables").string(), "--out-dir", (dir / "lib").string(),
                                         "--model", "cook-torrance", "--metric", "E2", "--starts", "1", "--max-iterations", "20"};
  RunResult r = runGlossy(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("1 fits, 0 already done"), std::string::npos) << r.err;
  const MaterialFile m = loadMaterialFile(dir / "lib" / "alum-bronze.toml");
  ASSERT_EQ(m.fits.size(), parseMaterialToml(before, "before").fits.size() + 1);
  EXPECT_EQ(*m.findExact(FitId::parse("cook-torrance:E2", "test")),
            *parseMaterialToml(before, "before").findExact(FitId::parse("cook-torrance:E2", "test")));
  ASSERT_NE(m.findExact(FitId::parse("cook-torrance:E2:glossy", "test")), nullptr);
  r = runGlossy(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("1 fits, 1 already done"), std::string::npos) << r.err;
}

// Before 'by', glossy fit wrote its fits unmarked; a batch resumes past them still (their settings say
// whose they are), rather than fit them again.
TEST(CliFit, BatchResumesPastFitsAnEarlierGlossyWroteUnmarked) {
  TempDir dir;
  std::filesystem::create_directories(dir / "tables");
  writeText(dir / "tables" / "one.binary", tabulatedMerlBytes(kTruth));
  const std::vector<std::string> args = {"fit", "--measured-dir", (dir / "tables").string(), "--out-dir", (dir / "fits").string(),
                                         "--model", "cook-torrance", "--metric", "E1", "--starts", "1", "--max-iterations", "10"};
  ASSERT_EQ(runGlossy(args).status, 0);
  std::string text = readText(dir / "fits" / "one.toml");
  for (const std::string cut : {"by = \"glossy\"\n", "data = \"one.binary\"\n", "database = \"MERL\"\n"})
    text.erase(text.find(cut), cut.size());
  text = std::regex_replace(text, std::regex("date = .*\n"), "");
  writeText(dir / "fits" / "one.toml", text);
  const RunResult r = runGlossy(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("1 fits, 1 already done"), std::string::npos) << r.err;
}

TEST(CliError, PublishedFitsAgainstTheSharedTablesGiveFiniteErrors) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  const RunResult r = runGlossy({"error", "--measured", (sharedDir() / "merl" / "alum-bronze.binary.xz").string(), "--material",
                                 (materialsDir() / "alum-bronze.toml").string(), "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json["fits"].size(), loadMaterialFile(materialsDir() / "alum-bronze.toml").fits.size());
  for (const auto& f : json["fits"]) {
    EXPECT_TRUE(std::isfinite(f["E1"].get<double>()) && f["E1"].get<double>() > 0.0) << f;
    EXPECT_TRUE(std::isfinite(f["E2"].get<double>()) && f["E2"].get<double>() > 0.0) << f;
  }
}

}  // namespace glossy::test
