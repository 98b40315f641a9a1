// glossy fit and glossy error through the command line (shared/spec/interfaces.md), on MERL-format
// tables the tests write; and the published fits against shared/merl's tables.
#include "materials/fitting/metric.h"
#include "materials/params/material_file.h"
#include "tests/support/test_support.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>

namespace glossy::test {

namespace {

const Brdf kTruth = CookTorrance{Rgb(0.1, 0.08, 0.05), Rgb(0.4, 0.3, 0.25), 0.08, 1.7};

std::filesystem::path writeTable(const TempDir& dir, const std::string& name, const Brdf& brdf,
                                 const BinPredicate& unmeasured = {}) {
  const std::filesystem::path path = dir / (name + ".binary");
  writeText(path, tabulatedMerlBytes(brdf, unmeasured));
  return path;
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
  EXPECT_NE(r.err.find("cook-torrance:E1: E1 = "), std::string::npos) << r.err;

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
    if (f["fit"] != "cook-torrance:E1") continue;
    seen = true;
    EXPECT_NEAR(f["E1"].get<double>(), *fit->error, 1e-12);
    EXPECT_NEAR(f["stored"].get<double>(), *fit->error, 0.0);
    EXPECT_GT(f["E2"].get<double>(), 0.0);
  }
  EXPECT_TRUE(seen) << e.out;
  EXPECT_EQ(json["validPairs"].get<size_t>(), MetricGrid::kPairs);

  const RunResult t = runGlossy({"error", "--measured", table.string(), "--material", toml.string()});
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("cook-torrance:E1"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("ashikhmin-shirley:E2"), std::string::npos) << t.out;
}

TEST(CliFit, WithoutAnOutputFileWritesTheNewMaterialToStdout) {
  TempDir dir;
  const auto table = writeTable(dir, "plain", Lambertian{Rgb(0.3, 0.2, 0.1)});
  const RunResult r = runGlossy({"fit", "--measured", table.string(), "--model", "ashikhmin-shirley", "--metric", "E2", "--starts", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  const MaterialFile m = parseMaterialToml(r.out, "stdout");
  EXPECT_EQ(m.name, "plain");
  EXPECT_EQ(m.measured, "plain.binary");
  ASSERT_EQ(m.fits.size(), 1u);
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

TEST(CliError, PublishedFitsAgainstTheSharedTablesGiveFiniteErrors) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  const RunResult r = runGlossy({"error", "--measured", (sharedDir() / "merl" / "alum-bronze.binary.xz").string(), "--material",
                                 (sourceDir() / "materials" / "alum-bronze.toml").string(), "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json["fits"].size(), 6u);
  for (const auto& f : json["fits"]) {
    EXPECT_TRUE(std::isfinite(f["E1"].get<double>()) && f["E1"].get<double>() > 0.0) << f;
    EXPECT_TRUE(std::isfinite(f["E2"].get<double>()) && f["E2"].get<double>() > 0.0) << f;
  }
}

}  // namespace glossy::test
